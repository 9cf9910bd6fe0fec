// Cost against quality as an SVG scatter plot with its Pareto front (no cheaper point is better).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace app {

struct ScatterPoint {
  std::string label;
  double cost = 0;     // x: lower is better
  double quality = 0;  // y: higher is better
  bool highlighted = false;
};

struct ScatterOptions {
  std::string xLabel, yLabel;
  std::optional<double> target;       // a horizontal line at this quality, labelled "target"
  std::string highlightMeaning = "";  // the legend's word for highlighted points ("chosen"); none if empty
};

// The Pareto front of `points`: the indices of those no cheaper point beats in quality, cheapest first
// (of equal cost the best first, so only it can join). The one definition the plot and the tuner use.
std::vector<size_t> paretoFront(const std::vector<ScatterPoint>& points);

// Every point is labelled; labels are placed where they overlap neither another label nor a point,
// with a leader line when they had to move away. A legend names the front (and the highlight).
std::string svgScatter(const std::vector<ScatterPoint>& points, const ScatterOptions& options);

}  // namespace app
