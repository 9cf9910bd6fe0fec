#include "frame_statistics.h"

namespace retroaa {

GLuint FrameStatistics::QueryPool::next(ObjectCounter& objects) {
  if (used == queries.size()) {
    GLuint name = 0;
    glGenQueries(1, &name);
    queries.emplace_back(objects, name);
  }
  return queries[used++].get();
}

FrameStatistics::Slot* FrameStatistics::openSlot() {
  Slot& slot = ring_[(frames_ + kFramesInFlight - 1) % kFramesInFlight];
  return frames_ > 0 && slot.state == Slot::State::Open ? &slot : nullptr;
}

void FrameStatistics::closeFrame() {
  if (Slot* open = openSlot()) {
    if (passDepth_ > 0) endPass();  // a pass left open by an error return
    open->state = Slot::State::Pending;
  }
}

void FrameStatistics::beginFrame() {
  closeFrame();
  collect();
  Slot& slot = ring_[frames_ % kFramesInFlight];
  // A slot still pending here (the GPU this far behind) is dropped, never waited for: its queries are
  // begun anew, which discards their results.
  slot.frame = ++frames_;
  slot.state = Slot::State::Open;
  slot.passes.clear();
  slot.evaluationCounts.clear();
  slot.timePool.used = slot.fragmentPool.used = slot.computePool.used = slot.samplesPool.used = 0;
  passDepth_ = 0;
}

void FrameStatistics::beginPass(const char* name, bool measured, uint64_t minimumBytes, uint64_t bytesPerInvocation) {
  Slot* slot = openSlot();
  if (!slot || !measured || passDepth_++ > 0) return;
  PassQueries pass{name, 0, 0, 0, minimumBytes, bytesPerInvocation, {}};
  if (timerQueries_) {
    // A tiling rasterizer (llvmpipe, a mobile GPU) runs a query begun while the previous target's draws
    // are still binned inside each of their tiles, so the timer would span the whole earlier pass (the
    // host's G-buffer: STK cornfield_crossing's resolve read 14.3 ms, 3.7 without it). A flush closes
    // that batch first; it never waits.
    glFlush();
    pass.time = slot->timePool.next(queries_);
    glBeginQuery(GL_TIME_ELAPSED, pass.time);
  }
  if (pipelineStatistics_) {
    pass.fragments = slot->fragmentPool.next(queries_);
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS, pass.fragments);
    pass.computes = slot->computePool.next(queries_);
    glBeginQuery(GL_COMPUTE_SHADER_INVOCATIONS, pass.computes);
  }
  slot->passes.push_back(std::move(pass));
}

void FrameStatistics::endPass() {
  if (passDepth_ == 0 || --passDepth_ > 0) return;
  const PassQueries& pass = openSlot()->passes.back();
  if (pass.time) glEndQuery(GL_TIME_ELAPSED);
  if (pass.fragments) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS);
  if (pass.computes) glEndQuery(GL_COMPUTE_SHADER_INVOCATIONS);
}

void FrameStatistics::addUnmeasuredPass(const std::string& name, const std::string& reason) {
  if (Slot* slot = openSlot()) slot->passes.push_back({name, 0, 0, 0, 0, 0, reason});
}

GLuint FrameStatistics::beginEvaluationCount() {
  Slot* slot = openSlot();
  if (!slot) return 0;
  const GLuint query = slot->samplesPool.next(queries_);
  slot->evaluationCounts.push_back({query, 0});
  glBeginQuery(GL_SAMPLES_PASSED, query);
  return query;
}

void FrameStatistics::endEvaluationCount() {
  if (openSlot()) glEndQuery(GL_SAMPLES_PASSED);
}

void FrameStatistics::addEvaluations(uint64_t pixels) {
  if (Slot* slot = openSlot()) slot->evaluationCounts.push_back({0, pixels});
}

bool FrameStatistics::available(const Slot& slot) const {
  auto isAvailable = [](GLuint query) {
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &ready);
    return ready == GL_TRUE;
  };
  for (const PassQueries& pass : slot.passes)
    for (GLuint query : {pass.time, pass.fragments, pass.computes})
      if (query && !isAvailable(query)) return false;
  for (const Slot::EvaluationCount& count : slot.evaluationCounts)
    if (count.query && !isAvailable(count.query)) return false;
  return true;
}

void FrameStatistics::read(Slot& slot, GLenum resultMode) {
  auto result = [resultMode](GLuint query) {
    GLuint64 value = 0;
    if (query) glGetQueryObjectui64v(query, resultMode, &value);
    return uint64_t(value);
  };
  FrameFigures figures;
  figures.frame = slot.frame;
  for (const Slot::EvaluationCount& count : slot.evaluationCounts)
    figures.lightingEvaluationsBySlice.push_back(count.query ? result(count.query) : count.pixels);
  for (const PassQueries& pass : slot.passes) {
    const uint64_t fragments = result(pass.fragments), computes = result(pass.computes);
    // Without pipeline statistics a floor's invocations, so its bytes, are unknown: 0, not a guess.
    const uint64_t bytes = pass.minimumBytes ? pass.minimumBytes : pass.bytesPerInvocation * (fragments + computes);
    figures.passes.push_back(
        {pass.name, double(result(pass.time)) * 1e-6, fragments, computes, bytes, pass.unmeasured});
  }
  slot.state = Slot::State::Empty;
  if (figures.frame > latest_.frame) latest_ = std::move(figures);
}

bool FrameStatistics::collect() {
  const uint64_t before = latest_.frame;
  // Oldest first, so that `latest_` ends at the newest frame that is back.
  for (uint64_t frame = frames_ > kFramesInFlight ? frames_ - kFramesInFlight + 1 : 1; frame <= frames_; ++frame) {
    Slot& slot = ring_[(frame - 1) % kFramesInFlight];
    if (slot.frame != frame || slot.state != Slot::State::Pending) continue;
    if (!available(slot)) break;  // later frames finish later
    // Available: GL_QUERY_RESULT_NO_WAIT returns the value at once (and can never wait).
    read(slot, GL_QUERY_RESULT_NO_WAIT);
  }
  return latest_.frame > before;
}

void FrameStatistics::waitForLastFrame() {
  closeFrame();
  for (uint64_t frame = frames_ > kFramesInFlight ? frames_ - kFramesInFlight + 1 : 1; frame <= frames_; ++frame) {
    Slot& slot = ring_[(frame - 1) % kFramesInFlight];
    if (slot.frame == frame && slot.state == Slot::State::Pending) read(slot, GL_QUERY_RESULT);
  }
}

void FrameStatistics::release() {
  if (passDepth_ > 0) endPass();
  for (Slot& slot : ring_) slot = Slot{};
  latest_ = FrameFigures{};
}

}  // namespace retroaa
