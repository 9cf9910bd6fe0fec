// `retroaa regress`: every frame of recorded demo scenes with every method, against the per-sample
// reference and ground truth; a report a person reads (report.html) and one a machine reads
// (report.json); goldens that catch regressions.
#pragma once

#include "retroaa/config.h"

#include <string>
#include <vector>

namespace app {

struct RegressOptions {
  std::vector<std::string> scenes;  // empty: the five recorded scenes of integration-tests/scenes
  std::string host = "fso";         // the host engine; goldens of another host than fso are <scene>.<host>.json
  std::string methods = "each";     // one spec per method (expandMethodList)
  retroaa::Config base;
  int width = 240, height = 180;
  int groundTruthSamples = 6;  // per axis
  int frameStride = 1;         // every n-th frame of each path
  int maxFrames = 0;           // at most this many frames per scene (0: all)
  int wallFrames = 60;         // back-to-back frames of each scene's first frame for wall_ms (0: none)
  std::string out = "out/regress";
  std::string goldenDirectory;  // empty: the source tree's integration-tests/golden, from any working folder
  bool check = false;           // compare with the goldens; exit 1 naming what got worse
  bool updateGolden = false;    // rewrite the goldens from this run
};

// The scenes `regress` runs when none are named: relative to the source tree's integration-tests/.
std::vector<std::string> defaultRegressScenes(const std::string& integrationTestsDirectory);

int runRegress(const RegressOptions& options);

}  // namespace app
