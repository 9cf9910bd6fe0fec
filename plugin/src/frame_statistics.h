// The plugin's GPU statistics without a GPU→CPU wait in the frame path: each frame's queries (pass
// times, fragment-shader invocations, pixels lit) go into one slot of a ring and are read frames later,
// once the driver reports them available. waitForLastFrame() is the one place that waits, for tools.
#pragma once

#include "gl_resources.h"
#include "retroaa/types.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace retroaa {

// What one frame measured once its queries are back.
struct FrameFigures {
  uint64_t frame = 0;                                // 1 for the first frame the plugin ran; 0: none back yet
  std::vector<uint64_t> lightingEvaluationsBySlice;  // pixels lit, one per lighting call (a slice), in order
  std::vector<PassStats> passes;
};

class FrameStatistics {
 public:
  // Frames whose queries may be outstanding at once. A slot still unread when its turn comes again
  // (the GPU more than this many frames behind) is dropped rather than waited for.
  static constexpr size_t kFramesInFlight = 4;

  FrameStatistics(bool timerQueries, bool pipelineStatistics)
      : timerQueries_(timerQueries), pipelineStatistics_(pipelineStatistics) {}

  // Closes the frame in flight, reads every finished one (never waits) and opens the next.
  void beginFrame();
  // Pass queries, when `measured`: a timer and, where the context has pipeline statistics, a
  // fragment-invocation count. A pass inside another pass is not measured on its own.
  // `bytesPerInvocation`: the pass's minimum bytes are that times its invocations (a floor's).
  void beginPass(const char* name, bool measured, uint64_t minimumBytes = 0, uint64_t bytesPerInvocation = 0);
  void endPass();
  // A pass of the frame that could not be measured, and why (PassStats::unmeasured).
  void addUnmeasuredPass(const std::string& name, const std::string& reason);
  // Pixels lit: counted on the GPU by an occlusion query around a draw that passes exactly where the
  // lighting will run, or added directly where the CPU knows the number. beginEvaluationCount returns
  // the query (0 outside a frame), which may serve as a conditional-rendering predicate.
  GLuint beginEvaluationCount();
  void endEvaluationCount();
  void addEvaluations(uint64_t pixels);

  // Reads every frame whose queries are available, without waiting. Returns true when a newer frame
  // came back since the last call.
  bool collect();
  // Waits for the GPU to finish the frame in flight (or the last closed one) and reads it.
  void waitForLastFrame();
  // Forgets every frame, pending or read, and frees the queries (a new method or size starts afresh).
  void release();
  const FrameFigures& latest() const { return latest_; }
  uint64_t framesStarted() const { return frames_; }
  // The ring's query objects: counted apart from the plugin's other objects, since they follow the
  // passes measured (at most kFramesInFlight × (3 per pass + 1 per slice)), not the method's targets.
  int queriesHeld() const { return queries_.live; }

 private:
  // Query objects keep the target of their first use, so each target has its own pool per slot.
  struct QueryPool {
    std::vector<GlQuery> queries;
    size_t used = 0;
    GLuint next(ObjectCounter& objects);
  };
  struct PassQueries {
    std::string name;
    GLuint time = 0, fragments = 0, computes = 0;
    uint64_t minimumBytes = 0, bytesPerInvocation = 0;
    std::string unmeasured;
  };
  struct Slot {
    uint64_t frame = 0;
    enum class State : uint8_t { Empty, Open, Pending } state = State::Empty;
    std::vector<PassQueries> passes;
    // One per lighting call: an occlusion query, or the pixels where the CPU knows them (query 0).
    struct EvaluationCount {
      GLuint query = 0;
      uint64_t pixels = 0;
    };
    std::vector<EvaluationCount> evaluationCounts;
    QueryPool timePool, fragmentPool, computePool, samplesPool;
  };
  void closeFrame();  // the frame in flight, if any, becomes pending
  bool available(const Slot& slot) const;
  void read(Slot& slot, GLenum resultMode);
  Slot* openSlot();

  ObjectCounter queries_;
  bool timerQueries_, pipelineStatistics_;
  std::array<Slot, kFramesInFlight> ring_;
  uint64_t frames_ = 0;
  int passDepth_ = 0;
  FrameFigures latest_;
};

}  // namespace retroaa
