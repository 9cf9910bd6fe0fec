// Cost against quality as an SVG scatter plot with its Pareto front (no cheaper point is better).
#pragma once

#include <string>
#include <vector>

namespace app {

struct ScatterPoint {
  std::string label;
  double cost = 0;     // x: lower is better
  double quality = 0;  // y: higher is better
  bool highlighted = false;
};

std::string svgScatter(const std::vector<ScatterPoint>& points, const std::string& xLabel, const std::string& yLabel);

}  // namespace app
