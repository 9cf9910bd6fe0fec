// The one measurement routine of bench, regress and tune: render a method on a frame, time it, count
// it, compare it; and the one set of field names every JSON and CSV report uses for the result.
#pragma once

#include "metrics.h"
#include "session.h"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace app {

// What a frame's renders are judged against.
struct FrameReference {
  std::vector<uint8_t> truthRgba;  // ground truth, display RGBA8 top-down
  DisplayImage truth;              // the same as metric values
  std::vector<uint8_t> edges;      // ground-truth edge pixels (metrics.h), the background's detail's too
  // The same split: the models' and the scene's edges, and those only the background's own detail (stars)
  // makes. Empty where the background has none: then `edges` are the models'.
  std::vector<uint8_t> modelEdges, backgroundEdges;
  std::optional<DisplayImage> perSample;  // the per-sample render at the run's sample count
  // Where the ground truth changed since the previous frame (markChangedSince; empty: not computed): with
  // a still camera, what objects that move covered or uncovered. A history's error there is its lag.
  std::vector<uint8_t> changed;
};
// Ground truth of `camera` (`samplesPerAxis`² lit supersamples per pixel) and, with
// `perSampleBase`, the per-sample render under that config (its method replaced, no filter stacked).
FrameReference renderReference(Session& session, const host::Camera& camera, int samplesPerAxis,
                               const retroaa::Config* perSampleBase);
// Fills `reference.changed`: the pixels where `previousTruthRgba` (the frame before's ground truth, display
// RGBA8 top-down) differs from `reference`'s by more than 4/255 in a channel.
void markChangedSince(const std::vector<uint8_t>& previousTruthRgba, FrameReference& reference);

struct Measurement {
  std::vector<uint8_t> display;  // RGBA8 top-down, of the last frame
  DisplayImage image;
  retroaa::Stats stats;  // of the last frame
  double gpuMs = 0;      // the host's frame on the GPU: median of the timed frames
  double wallMs = 0;     // wall clock per frame, statistics off (0: not measured)
  // Medians: model_pass (the host's geometry alone), after_model_pass (its hooks: resolve, a prepass),
  // lighting, tonemap_post, plugin.<pass>.
  std::map<std::string, double> passMs;
  // plugin.<pass> run more than once a frame (once per slice): each run's median ms, in frame order.
  std::map<std::string, std::vector<double>> passMsByRun;
  std::map<std::string, uint64_t> passInvocations;         // plugin.<pass>: fragment-shader invocations, last frame
  std::map<std::string, uint64_t> passComputeInvocations;  // … compute-shader invocations (passes with any)
  std::map<std::string, uint64_t> passMinimumBytes;        // plugin.<pass>: its least traffic, where stated
  // Each plugin pass's floor (measure_pass_floors, frames of their own after the timed ones): medians of
  // its ms, the bytes it moved, and for a floor that could not be measured, why (no ms then).
  std::map<std::string, double> passFloorMs;
  std::map<std::string, uint64_t> passFloorBytes;
  std::map<std::string, std::string> passFloorUnmeasured;
  ErrorMetrics error;  // against the ground truth, edge figures on its edges
  // Edge figures on the models' edges and on the background's own (FrameReference): the edge figures of
  // their pixelErrors, absent where the reference does not split its edges.
  std::optional<ErrorMetrics> modelEdgeError, backgroundEdgeError;
  std::optional<double> psnrVsPerSampleDb;
};
// How a history converges on a still camera: `frames` frames of it from a fresh history,
// each scored against the ground truth.
struct Convergence {
  std::vector<double> psnrDb;    // after each frame
  double convergedPsnrDb = 0;    // the mean over the last `round` frames (a round of the jitter sequence)
  int framesToWithinOneDb = -1;  // the first frame from which every frame scores within 1 dB of it
};
Convergence measureConvergence(Session& session, const host::Camera& camera, const FrameReference& reference,
                               int frames, int round);
// Renders `camera` with the session's config: `wallFrames` back-to-back frames with every statistic
// off and no wait until the last (wall_ms: the time an engine sees), then `warmUpFrames` frames
// (shader compilation, first-touch allocation), then `timedFrames` with GPU timers and the plugin's
// pass statistics; compares the last. Then, with `floorFrames`, one warm-up and that many frames with
// each pass's floor (measure_pass_floors), which add their own GPU work and so are timed apart.
Measurement measure(Session& session, const host::Camera& camera, const FrameReference& reference, int timedFrames,
                    int warmUpFrames, int wallFrames = 0, int floorFrames = 0);
// The shading floor of the frame: per pixel, the distinct surfaces among its samples (bit-identical
// attributes: one primitive), averaged — the fewest lighting evaluations per pixel a method can do and
// still light every surface a pixel shows. Renders `camera` once with `resolve` at the session's
// sample count (for its MSAA G-buffer), then restores the session's config. 1 at one sample.
double measureShadingFloor(Session& session, const host::Camera& camera);
// The GPU's copy bandwidth (GB/s, read + write): a 64 MiB RGBA32F texture copied back and forth, timed
// with a timer query. What a pass's minimum bytes are divided by for its traffic bound.
double measureCopyGigabytesPerSecond();
// Wall-clock ms per frame over `frames` back-to-back frames of the session's config with its
// statistics off, after one warm-up frame; waits for the GPU only before and after.
double measureWallMs(Session& session, const host::Camera& camera, int frames);

// The figures of a measurement by the names every report uses: samples, evals_per_pixel,
// lighting_evaluations, slices, gpu_ms, wall_ms (null when not measured), passes_ms,
// passes_fragment_invocations, passes_compute_invocations, passes_minimum_bytes, passes_ms_by_run (a pass run
// once per slice: each run's ms, so a sparse slice's cost shows beside a full one's), plugin_bytes,
// plugin_bytes_per_pixel, budget_scale, psnr_db, edge_psnr_db (null when the ground truth has no edge pixel),
// edge_pixels, ssim, max_abs_error, psnr_vs_per_sample_db (when measured).
nlohmann::json figures(const Measurement& measurement);

// Adds to rows (each with "method" and figures()'s names) the ratios to baselines measured in the same
// run: time_vs_off, time_vs_per_sample, wall_vs_off, and plugin_overhead_ms = gpu_ms − model_pass −
// evals_per_pixel × off's lighting − off's tonemap_post. Null where the baseline was not run or the
// time not measured.
void addTimeRatios(nlohmann::json& rows);

// Adds passes_floor_ratio (each pass's ms over its floor's, where both were measured), plugin_own_ms (every
// plugin pass but the host's lighting inside the slices) and plugin_own_vs_off_frame (that over off's
// gpu_ms in the same run; null without off).
void addFloorRatios(nlohmann::json& rows);

// Adds passes_traffic_bound_ms: each pass's minimum bytes at the copy bandwidth (ms).
void addTrafficBounds(nlohmann::json& rows, double copyGigabytesPerSecond);

// The quality figures a target can name, and the cost figures tune can minimise.
const std::vector<std::string>& qualityFigures();  // psnr_db, edge_psnr_db, interior_psnr_db, ssim
const std::vector<std::string>& costFigures();     // evals_per_pixel, gpu_ms, plugin_bytes_per_pixel

}  // namespace app
