// `retroaa tune`: the cheapest settings that meet a quality target on the user's own scenes.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace app {

// A quality target: `metric` is a quality figure (measure.h: psnr_db, edge_psnr_db, ssim) that must
// reach `threshold` on every frame of every scene.
struct TuneTarget {
  std::string metric;
  double threshold = 0;
};
TuneTarget parseTuneTarget(const std::string& text);  // "edge_psnr_db=35"; throws std::invalid_argument

// One candidate setting, measured: its cost (mean over frames) and its metrics on every frame.
struct TunePoint {
  std::string spec;
  double cost = 0;
  std::vector<std::map<std::string, double>> frames;
  int requestedSamples = 1, grantedSamples = 1;  // MSAA samples the spec asks for and the driver gave
};

struct TuneChoice {
  bool feasible = false;
  int chosen = -1;         // the cheapest feasible point, or (infeasible) the one closest to the targets
  int nextCheaper = -1;    // the cheapest point below the chosen one on the front, if any
  std::vector<int> front;  // Pareto front of cost against the first target's worst frame, cheapest first
};

// Pure and deterministic: ties in cost go to the better worst frame, then to the earlier point.
TuneChoice chooseCheapest(const std::vector<TunePoint>& points, const std::vector<TuneTarget>& targets);

struct TuneOptions {
  std::vector<std::string> scenes = {"default"};
  std::vector<TuneTarget> targets;
  std::string cost = "evals_per_pixel";  // a cost figure (measure.h): evals_per_pixel | gpu_ms | plugin_bytes_per_pixel
  std::string candidates;                // comma-separated specs; empty: the built-in grid
  int width = 160, height = 120, groundTruthSamples = 4, frames = 4;
  std::string out = "out/tune/config.cfg";
  std::string cache = "out/tune/cache.json";  // measured points, reused by later runs
};
int runTune(const TuneOptions& options);

}  // namespace app
