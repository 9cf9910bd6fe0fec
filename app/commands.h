// The `retroaa` subcommands as functions, so tests call them without a process in between.
#pragma once

#include "retroaa/config.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace app {

// Exit codes of every subcommand.
constexpr int kExitOk = 0;
constexpr int kExitCheckFailed = 1;
constexpr int kExitBadInput = 2;

// A method as named in reports and on the command line: `method[/weighting][+stacked][@key=value]...`,
// e.g. `off`, `resolve`, `resolve/fso`, `resolve@samples=8`, and `resolve+NAME` for a method that stacks
// (MethodInfo::stackKey).
// Settings (--set, --config) apply first, then the spec's own.
struct MethodSpec {
  std::string name;
  retroaa::Config config;
};
// Throws std::invalid_argument naming the bad part.
MethodSpec parseMethodSpec(const std::string& spec, const retroaa::Config& base);
// What the tools render of one method, as comma-separated method specs: a full sweep (`--methods all`,
// the viewer's M key), the one spec a regression run renders (`each`), and the points `retroaa tune`
// searches, cheapest first (`grid`). A method with no variants listed here is its plain name in all three.
struct ToolSpecs {
  std::string sweep, regress, tune;
};
ToolSpecs toolSpecs(const retroaa::MethodInfo& method);
// Keywords expand from the plugin's method registry: "all" to every method with its variants (resolve
// weightings, stacking), "each" to one spec per method, "grid" to the settings `tune` searches.
std::vector<std::string> expandMethodList(const std::string& list);
// expandMethodList, each spec parsed over `base`; throws std::invalid_argument naming a bad spec, or
// when the list names no method.
std::vector<MethodSpec> parseMethodList(const std::string& list, const retroaa::Config& base);

// Each slice's pixels lit and GPU ms, what a sparse slice costs beside a full one: rows with
// "passes_ms_by_run" (a pass's ms per run, in slice order, keyed by `passPrefix` + its name) and
// "lighting_evaluations_by_slice", each named by its `nameKey` field. Empty when no row has slices.
std::string sliceTable(const nlohmann::json& rows, const std::string& nameKey, const std::string& passPrefix);

struct RenderOptions {
  std::string scene = "default";
  std::string host = "fso";  // the host engine (app::hostNames())
  std::string method;        // a MethodSpec, "ground-truth", or empty: the config's own method
  retroaa::Config base;      // from --config / --set / FSO flags
  int width = 320, height = 240;
  int frame = -1;              // camera path frame; -1: the scene's camera
  int groundTruthSamples = 8;  // per axis, for --method ground-truth and --heatmap
  std::string out;             // .png or .exr (.exr writes linear radiance)
  std::string heatmap;         // optional: error heat map against ground truth
  std::string show;            // "" (the image), "edges" or "samples": visualise the slice counts
};

// Visualisations of per-pixel lighting evaluation counts (bottom-up counts, top-down RGBA8 image):
// "edges" dims the image and marks pixels lit more than once in magenta; "samples" maps the count
// 1 … maxCount onto a blue → green → red ramp.
std::vector<uint8_t> visualiseCounts(const std::string& view, const std::vector<uint8_t>& countsBottomUp,
                                     const std::vector<uint8_t>& displayTopDown, int width, int height, int maxCount);
int runRender(const RenderOptions& options);

struct BenchOptions {
  std::string scene = "default";
  std::string host = "fso";
  std::string methods = "all";
  retroaa::Config base;
  int width = 320, height = 240;
  int frame = -1;
  int groundTruthSamples = 8;
  int repeats = 3;                // timed frames per method; the median is reported
  int wallFrames = 60;            // back-to-back frames per method for wall_ms (0: not measured)
  int floorFrames = -1;           // frames timing each pass's floor (-1: as repeats; 0: not measured)
  std::string json, csv, report;  // outputs (any may be empty)
  std::string imagesDirectory;    // per-method PNGs and heat maps (optional)
};
int runBench(const BenchOptions& options);

// A camera path for a scene, recorded without a window: `keys` keys over `seconds`, orbiting the
// scene camera's target by `orbitDegrees` about the up axis and moving the camera to `dolly` × its
// distance. Written as the JSON a scene's "camera_path" takes (inline, or by file name).
struct RecordOptions {
  std::string scene = "default";
  float orbitDegrees = 30.0f;
  float dolly = 1.0f;
  float seconds = 1.0f;
  float framesPerSecond = 30.0f;
  int keys = 5;
  bool fit = false;  // orbit a camera that frames the scene's models instead of the scene's camera
  std::string out;
};
int runRecord(const RecordOptions& options);

// Soak: `frames` frames in one process, switching method, sample count, weighting, detector and
// size as it goes; checks that the plugin's GL objects return to their starting count, that no GL error
// is raised, and that resident memory stays within `maxGrowthMiB` after warm-up. Exit 1 if not.
struct SoakOptions {
  int frames = 2000;
  int width = 96, height = 72;
  double maxGrowthMiB = 64;
};
int runSoak(const SoakOptions& options);

// Every config key with default, allowed values and effect: plain text, or docs/config.md's table.
std::string configReference(bool markdown);

}  // namespace app
