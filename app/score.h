// `retroaa score`: frames a foreign engine captured with each method (SuperTuxKart's --aa-capture),
// scored against a supersampled reference render of the same frame: the speed-vs-error table `bench`
// writes for the in-repo hosts, from the engine's own images and figures.
#pragma once

#include <string>
#include <vector>

namespace app {

// A square of capture pixels: x, y from the top left, and its size.
struct Crop {
  int x = 0, y = 0, size = 0;
};
// A named rectangle of capture pixels scored apart (the kart, the wires).
struct Region {
  std::string name;
  int x = 0, y = 0, width = 0, height = 0;
};

struct ScoreOptions {
  std::string captureDir;  // capture.jsonl and the PNGs it names: one per method, or per method and frame
  // The same frame at `factor`× width and height, unfiltered; or, for frames of a sequence (records with
  // "frame"), the folder of the reference's own capture, whose records are matched by frame.
  std::string reference;
  int factor = 4;
  std::string out;              // report.md, report.json and crops/ (default: the capture folder)
  std::vector<Crop> crops;      // shown for every method (its last frame), 4× enlarged
  std::vector<Region> regions;  // PSNR and edge PSNR within each, per method
};
// "X,Y,SIZE" and "NAME=X,Y,W,H" as the command line gives them; std::invalid_argument naming the bad text.
Crop parseCrop(const std::string& text);
Region parseRegion(const std::string& text);

int score(const ScoreOptions& options);

}  // namespace app
