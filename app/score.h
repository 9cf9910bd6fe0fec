// `retroaa score`: frames a foreign engine captured with each method (SuperTuxKart's --aa-capture),
// scored against a supersampled reference render of the same frame: the speed-vs-error table `bench`
// writes for the in-repo hosts, from the engine's own images and figures.
#pragma once

#include <string>

namespace app {

struct ScoreOptions {
  std::string captureDir;  // capture.jsonl and one PNG per method
  std::string reference;   // the same frame at `factor`× width and height, unfiltered
  int factor = 4;
  std::string out;  // report.md, report.json and crops/ (default: the capture folder)
  // A crop shown for every method, in capture pixels: x, y, size (0: none).
  int cropX = 0, cropY = 0, cropSize = 0;
};

int score(const ScoreOptions& options);

}  // namespace app
