#include "measure.h"

#include "ground_truth.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>

namespace app {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

FrameReference renderReference(Session& session, const host::Camera& camera, int samplesPerAxis,
                               const retroaa::Config* perSampleBase) {
  const host::GroundTruth truth = host::renderGroundTruth(
      *session.renderer, camera, samplesPerAxis, host::TextureFootprint::Supersample, host::BackgroundEdges::Apart);
  const int w = session.renderer->width(), h = session.renderer->height();
  FrameReference reference;
  reference.truthRgba = truth.display;
  reference.truth = DisplayImage::fromRgba8(w, h, truth.display);
  reference.edges = edgeMaskFromSpread(truth.lumaStdDev);
  if (!truth.modelLumaStdDev.empty()) {
    reference.modelEdges = modelEdgeMask(truth.lumaStdDev, truth.modelLumaStdDev);
    reference.backgroundEdges.resize(reference.edges.size());
    for (size_t p = 0; p < reference.edges.size(); ++p)
      reference.backgroundEdges[p] = reference.edges[p] && !reference.modelEdges[p];
  }
  if (perSampleBase) {
    retroaa::Config config = *perSampleBase;
    config.method = retroaa::Method::PerSample;
    for (const retroaa::MethodInfo& row : retroaa::methodTable())  // the reference unfiltered
      if (*row.stackKey) retroaa::applySetting(config, row.stackKey, "off");
    session.configure(config);
    session.renderer->renderFrame(camera);
    reference.perSample = DisplayImage::fromRgba8(w, h, session.renderer->readDisplay());
  }
  return reference;
}

void markChangedSince(const std::vector<uint8_t>& previousTruthRgba, FrameReference& reference) {
  reference.changed.assign(reference.truthRgba.size() / 4, 0);
  for (size_t p = 0; p < reference.changed.size(); ++p)
    for (size_t c = 0; c < 3; ++c)
      if (std::abs(int(previousTruthRgba[p * 4 + c]) - int(reference.truthRgba[p * 4 + c])) > 4)
        reference.changed[p] = 1;
}

double measureWallMs(Session& session, const host::Camera& camera, int frames) {
  host::Engine& renderer = *session.renderer;
  retroaa::Config quiet = session.config;
  quiet.measureGpuTime = false;
  const std::string method = session.method;
  session.configure(quiet, method);
  renderer.measureTime = false;
  renderer.renderFrame(camera);  // warm-up: the reconfigure's first-frame work
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) renderer.renderFrame(camera);
  glFinish();  // the one wait, after the last frame: what an engine's swap would eventually wait for
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
  return elapsed.count() / frames;
}

double measureCopyGigabytesPerSecond() {
  // 64 MiB each way: larger than the caches, so the copy runs at memory bandwidth.
  const int side = 2048, copies = 5;
  GLuint textures[2] = {0, 0}, query = 0;
  glCreateTextures(GL_TEXTURE_2D, 2, textures);
  for (GLuint texture : textures) glTextureStorage2D(texture, 1, GL_RGBA32F, side, side);
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(textures[0], 0, GL_RGBA, GL_FLOAT, zero);
  glCopyImageSubData(textures[0], GL_TEXTURE_2D, 0, 0, 0, 0, textures[1], GL_TEXTURE_2D, 0, 0, 0, 0, side, side, 1);
  glGenQueries(1, &query);
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, query);
  for (int i = 0; i < copies; ++i)
    glCopyImageSubData(textures[i % 2], GL_TEXTURE_2D, 0, 0, 0, 0, textures[1 - i % 2], GL_TEXTURE_2D, 0, 0, 0, 0, side,
                       side, 1);
  glEndQuery(GL_TIME_ELAPSED);
  glFinish();
  const std::chrono::duration<double, std::nano> wall = std::chrono::steady_clock::now() - start;
  GLuint64 timer = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &timer);
  glDeleteQueries(1, &query);
  glDeleteTextures(2, textures);
  // The GPU's timer where it saw the copies; llvmpipe copies on the CPU outside its timeline (its timer
  // reads near 0), so there the wall clock between two glFinish calls.
  const double nanoseconds = double(timer) >= 0.1 * wall.count() ? double(timer) : wall.count();
  const double bytesMoved = 2.0 * double(side) * side * 16.0 * copies;  // read and write
  return nanoseconds > 0 ? bytesMoved / nanoseconds : 0.0;              // bytes per ns = GB/s
}

double measureShadingFloor(Session& session, const host::Camera& camera) {
  retroaa::Config previous = session.config;
  const std::string previousMethod = session.method;
  retroaa::Config msaa = previous;
  msaa.method = retroaa::Method::Resolve;
  session.configure(msaa, "resolve");
  session.renderer->renderFrame(camera);
  std::vector<GLuint> attachments;
  for (const retroaa::AttachmentRole role :
       {retroaa::AttachmentRole::Albedo, retroaa::AttachmentRole::ViewPosition, retroaa::AttachmentRole::NormalGloss,
        retroaa::AttachmentRole::Specular, retroaa::AttachmentRole::Emissive})
    if (const GLuint texture = session.plugin().multisampledAttachment(role)) attachments.push_back(texture);
  const int samples = session.plugin().stats().samples;
  const int w = session.renderer->width(), h = session.renderer->height();
  double mean = 1.0;
  if (!attachments.empty() && samples > 1) {
    const host::Program program("shaders/fullscreen.vert", "shaders/distinct_surfaces.frag",
                                "#define SAMPLES " + std::to_string(samples) + "\n#define ATTACHMENTS " +
                                    std::to_string(attachments.size()) + "\n");
    const host::Texture target = host::makeTexture2D(GL_R32F, w, h, "bench.distinct_surfaces");
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    const host::Framebuffer framebuffer(name);
    glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, target.get(), 0);
    host::checkFramebuffer(framebuffer.get(), "bench.distinct_surfaces");
    GLuint vertexArray = 0;
    glCreateVertexArrays(1, &vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program.get());
    for (size_t a = 0; a < attachments.size(); ++a) glBindTextureUnit(GLuint(a), attachments[a]);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDeleteVertexArrays(1, &vertexArray);
    std::vector<float> surfaces(size_t(w) * h);
    glGetTextureImage(target.get(), 0, GL_RED, GL_FLOAT, GLsizei(surfaces.size() * sizeof(float)), surfaces.data());
    double sum = 0;
    for (float count : surfaces) sum += count;
    mean = sum / double(surfaces.size());
    for (size_t a = 0; a < attachments.size(); ++a) glBindTextureUnit(GLuint(a), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
  }
  session.configure(previous, previousMethod);
  return mean;
}

Convergence measureConvergence(Session& session, const host::Camera& camera, const FrameReference& reference,
                               int frames, int round) {
  const retroaa::Config config = session.config;
  const std::string method = session.method;
  session.configure(retroaa::Config{}, "off");  // frees the history: the next frame starts a new one
  session.configure(config, method);
  Convergence result;
  const int w = session.renderer->width(), h = session.renderer->height();
  for (int i = 0; i < frames; ++i) {
    session.renderer->renderFrame(camera);
    const DisplayImage image = DisplayImage::fromRgba8(w, h, session.renderer->readDisplay());
    result.psnrDb.push_back(compare(image, reference.truth, reference.edges).psnrDb);
  }
  const int last = std::max(1, std::min(round, frames));
  for (int i = frames - last; i < frames; ++i) result.convergedPsnrDb += result.psnrDb[size_t(i)] / last;
  for (int i = frames; i > 0 && std::fabs(result.psnrDb[size_t(i - 1)] - result.convergedPsnrDb) <= 1.0; --i)
    result.framesToWithinOneDb = i;
  return result;
}

namespace {
// The floors of `measured`'s passes into `m`: a warm-up frame (the floors' programs and targets), then
// `frames` frames, each pass's floor summed per frame (a pass may run once per slice), medians kept.
void measureFloors(Session& session, const host::Camera& camera, const retroaa::Config& measured, int frames,
                   Measurement& m) {
  retroaa::Config floored = measured;
  floored.measurePassFloors = true;
  session.configure(floored, session.method);
  session.renderer->renderFrame(camera);
  std::map<std::string, std::vector<double>> floorMs;
  const std::string suffix = ".floor";
  for (int i = 0; i < frames; ++i) {
    session.renderer->renderFrame(camera);
    const retroaa::Stats stats = session.plugin().waitForStats();
    std::map<std::string, double> frameMs;
    m.passFloorBytes.clear();
    for (const retroaa::PassStats& pass : stats.passes) {
      if (pass.name.size() <= suffix.size() ||
          pass.name.compare(pass.name.size() - suffix.size(), suffix.size(), suffix))
        continue;
      const std::string name = "plugin." + pass.name.substr(0, pass.name.size() - suffix.size());
      if (!pass.unmeasured.empty()) {
        m.passFloorUnmeasured[name] = pass.unmeasured;
        continue;
      }
      frameMs[name] += pass.ms;
      m.passFloorBytes[name] += pass.minimumBytes;
    }
    for (const auto& [name, ms] : frameMs) floorMs[name].push_back(ms);
  }
  // A pass with any draw the floor cannot reproduce has no floor: a part of it would understate it.
  for (const auto& [name, values] : floorMs)
    if (!m.passFloorUnmeasured.count(name)) m.passFloorMs[name] = median(values);
  for (const auto& [name, reason] : m.passFloorUnmeasured) m.passFloorBytes.erase(name);
  session.configure(measured, session.method);
}
}  // namespace

Measurement measure(Session& session, const host::Camera& camera, const FrameReference& reference, int timedFrames,
                    int warmUpFrames, int wallFrames, int floorFrames) {
  host::Engine& renderer = *session.renderer;
  Measurement m;
  if (wallFrames > 0) m.wallMs = measureWallMs(session, camera, wallFrames);
  retroaa::Config measured = session.config;
  measured.measureGpuTime = true;
  session.configure(measured, session.method);
  renderer.measureTime = true;
  for (int i = 0; i < warmUpFrames; ++i) renderer.renderFrame(camera);
  std::vector<double> frameMs;
  std::map<std::string, std::vector<double>> passMs, runMs;
  for (int i = 0; i < std::max(timedFrames, 1); ++i) {
    renderer.renderFrame(camera);
    const host::HostTimings& t = renderer.timings();
    frameMs.push_back(t.frameMs);
    passMs["model_pass"].push_back(t.modelPassMs);
    passMs["after_model_pass"].push_back(t.afterModelPassMs);
    passMs["lighting"].push_back(t.lightingMs);
    passMs["tonemap_post"].push_back(t.tonemapMs);
    m.stats = session.plugin().waitForStats();
    std::map<std::string, std::vector<double>> frameRuns;
    for (const retroaa::PassStats& pass : m.stats.passes) frameRuns["plugin." + pass.name].push_back(pass.ms);
    for (const auto& [name, runs] : frameRuns)
      if (runs.size() > 1)
        for (size_t run = 0; run < runs.size(); ++run) runMs[name + "#" + std::to_string(run)].push_back(runs[run]);
    std::map<std::string, double> frameTotals;  // a pass runs once per slice: sum them per frame
    m.passInvocations.clear();
    m.passComputeInvocations.clear();
    m.passMinimumBytes.clear();
    for (const retroaa::PassStats& pass : m.stats.passes) {
      frameTotals["plugin." + pass.name] += pass.ms;
      m.passInvocations["plugin." + pass.name] += pass.fragmentInvocations;
      if (pass.computeInvocations) m.passComputeInvocations["plugin." + pass.name] += pass.computeInvocations;
      if (pass.minimumBytes) m.passMinimumBytes["plugin." + pass.name] += pass.minimumBytes;
    }
    for (const auto& [name, ms] : frameTotals) passMs[name].push_back(ms);
  }
  if (floorFrames > 0) measureFloors(session, camera, measured, floorFrames, m);
  renderer.measureTime = false;
  m.display = renderer.readDisplay();
  m.image = DisplayImage::fromRgba8(renderer.width(), renderer.height(), m.display);
  m.gpuMs = median(frameMs);
  for (const auto& [name, values] : passMs) m.passMs[name] = median(values);
  for (const auto& [key, values] : runMs) {  // "plugin.<pass>#<run>", runs in order
    const size_t hash = key.rfind('#');
    std::vector<double>& runs = m.passMsByRun[key.substr(0, hash)];
    const size_t run = std::stoul(key.substr(hash + 1));
    if (runs.size() <= run) runs.resize(run + 1, 0.0);
    runs[run] = median(values);
  }
  m.error = compare(m.image, reference.truth, reference.edges);
  if (!reference.modelEdges.empty()) {
    m.modelEdgeError = pixelErrors(m.image, reference.truth, reference.modelEdges);
    m.backgroundEdgeError = pixelErrors(m.image, reference.truth, reference.backgroundEdges);
  }
  if (reference.perSample) m.psnrVsPerSampleDb = compare(m.image, *reference.perSample, {}).psnrDb;
  return m;
}

namespace {
// An edge PSNR, or null where there was no edge pixel to measure (never a made-up number).
nlohmann::json edgeFigure(const std::optional<ErrorMetrics>& error) {
  return error && error->edgePixels > 0 ? nlohmann::json(error->edgePsnrDb) : nlohmann::json(nullptr);
}
}  // namespace

nlohmann::json figures(const Measurement& m) {
  using nlohmann::json;
  json out = {
      {"samples", m.stats.samples},
      {"evals_per_pixel", m.stats.evaluationsPerPixel()},
      {"lighting_evaluations", m.stats.lightingEvaluations},
      {"lighting_evaluations_by_slice", m.stats.lightingEvaluationsBySlice},
      {"slices", m.stats.slices},
      {"gpu_ms", m.gpuMs},
      // Not measured (wall frames 0): null, never a made-up number.
      {"wall_ms", m.wallMs > 0 ? json(m.wallMs) : json(nullptr)},
      {"passes_ms", m.passMs},
      {"passes_ms_by_run", m.passMsByRun},
      {"passes_fragment_invocations", m.passInvocations},
      {"passes_compute_invocations", m.passComputeInvocations},
      {"passes_minimum_bytes", m.passMinimumBytes},
      {"passes_floor_ms", m.passFloorMs},
      {"passes_floor_bytes", m.passFloorBytes},
      {"passes_floor_unmeasured", m.passFloorUnmeasured},
      {"plugin_bytes", m.stats.bytesHeld},
      {"plugin_bytes_per_pixel", m.stats.pixels ? double(m.stats.bytesHeld) / double(m.stats.pixels) : 0.0},
      {"budget_scale", m.stats.budgetScale},
      {"psnr_db", m.error.psnrDb},
      // No edge pixel in the ground truth: there is no edge error to report (null, not a number).
      {"edge_psnr_db", m.error.edgePixels > 0 ? json(m.error.edgePsnrDb) : json(nullptr)},
      {"edge_pixels", m.error.edgePixels},
      // The models' edges apart from the background's own detail (stars), where the scene has any.
      {"model_edge_psnr_db", edgeFigure(m.modelEdgeError ? m.modelEdgeError : m.error)},
      {"model_edge_pixels", (m.modelEdgeError ? *m.modelEdgeError : m.error).edgePixels},
      {"background_edge_psnr_db", edgeFigure(m.backgroundEdgeError)},
      {"background_edge_pixels", m.backgroundEdgeError ? m.backgroundEdgeError->edgePixels : 0},
      // Every pixel an edge: no interior to report.
      {"interior_psnr_db", m.error.interiorPixels > 0 ? json(m.error.interiorPsnrDb) : json(nullptr)},
      {"ssim", m.error.ssim},
      {"max_abs_error", m.error.maxAbsError},
  };
  if (m.psnrVsPerSampleDb) out["psnr_vs_per_sample_db"] = *m.psnrVsPerSampleDb;
  return out;
}

void addTimeRatios(nlohmann::json& rows) {
  using nlohmann::json;
  auto baseline = [&rows](const char* method, const char* figure) {
    for (const json& row : rows)
      if (row["method"] == method && row[figure].is_number()) return row[figure].get<double>();
    return 0.0;
  };
  auto ratio = [](const json& value, double base) {
    return value.is_number() && base > 0 ? json(value.get<double>() / base) : json(nullptr);
  };
  const double offMs = baseline("off", "gpu_ms"), perSampleMs = baseline("per-sample", "gpu_ms");
  const double offWallMs = baseline("off", "wall_ms");
  const json* off = nullptr;
  for (const json& row : rows)
    if (row["method"] == "off") off = &row;
  for (json& row : rows) {
    row["time_vs_off"] = ratio(row["gpu_ms"], offMs);
    row["time_vs_per_sample"] = ratio(row["gpu_ms"], perSampleMs);
    row["wall_vs_off"] = ratio(row["wall_ms"], offWallMs);
    // What the method adds beyond the host's own model pass, the lighting its evaluations cost at off's
    // price, and off's tonemap and post.
    const json& passes = row["passes_ms"];
    row["plugin_overhead_ms"] =
        off && passes.contains("model_pass")
            ? json(row["gpu_ms"].get<double>() - passes["model_pass"].get<double>() -
                   row["evals_per_pixel"].get<double>() * (*off)["passes_ms"]["lighting"].get<double>() -
                   (*off)["passes_ms"]["tonemap_post"].get<double>())
            : json(nullptr);
  }
}

void addFloorRatios(nlohmann::json& rows) {
  using nlohmann::json;
  double offFrameMs = 0;
  for (const json& row : rows)
    if (row["method"] == "off") offFrameMs = row["gpu_ms"].get<double>();
  for (json& row : rows) {
    json ratios = json::object();
    double ownMs = 0;
    for (const auto& [pass, ms] : row["passes_ms"].items()) {
      if (pass.rfind("plugin.", 0) != 0) continue;
      // The host's lighting runs inside slices.lighting (with the plugin's clears of its targets): a
      // slice method must pay it; every other plugin pass is the plugin's own.
      if (pass != "plugin.slices.lighting" && pass != "plugin.lighting") ownMs += ms.get<double>();
      const json& floor = row.value("passes_floor_ms", json::object());
      if (floor.contains(pass) && floor[pass].get<double>() > 0)
        ratios[pass] = ms.get<double>() / floor[pass].get<double>();
    }
    row["passes_floor_ratio"] = ratios;
    row["plugin_own_ms"] = ownMs;
    row["plugin_own_vs_off_frame"] = offFrameMs > 0 ? json(ownMs / offFrameMs) : json(nullptr);
  }
}

void addTrafficBounds(nlohmann::json& rows, double copyGigabytesPerSecond) {
  for (nlohmann::json& row : rows) {
    nlohmann::json bounds = nlohmann::json::object();
    if (copyGigabytesPerSecond > 0)
      for (const auto& [pass, bytes] : row["passes_minimum_bytes"].items())
        bounds[pass] = bytes.get<double>() / (copyGigabytesPerSecond * 1e6);
    row["passes_traffic_bound_ms"] = bounds;
  }
}

const std::vector<std::string>& qualityFigures() {
  static const std::vector<std::string> names = {"psnr_db", "edge_psnr_db", "interior_psnr_db", "ssim"};
  return names;
}

const std::vector<std::string>& costFigures() {
  static const std::vector<std::string> names = {"evals_per_pixel", "gpu_ms", "plugin_bytes_per_pixel"};
  return names;
}

}  // namespace app
