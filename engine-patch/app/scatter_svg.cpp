// Speed-against-error scatter plots as SVG, for the regression report and the tuner.
#include "scatter_svg.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace app {

std::string svgScatter(const std::vector<ScatterPoint>& points, const std::string& xLabel, const std::string& yLabel) {
  // Cost (GPU ms) against edge PSNR, with the Pareto front: no cheaper point is better.
  const double w = 560, h = 300, left = 60, bottom = 40, top = 20, right = 20;
  double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
  for (const ScatterPoint& p : points) {
    xMin = std::min(xMin, p.cost), xMax = std::max(xMax, p.cost);
    yMin = std::min(yMin, p.quality), yMax = std::max(yMax, p.quality);
  }
  if (xMax <= xMin) xMax = xMin + 1;
  if (yMax <= yMin) yMax = yMin + 1;
  xMin = 0, yMin = std::floor(yMin - 1), yMax = std::ceil(yMax + 1), xMax *= 1.1;
  auto px = [&](double v) { return left + (v - xMin) / (xMax - xMin) * (w - left - right); };
  auto py = [&](double v) { return h - bottom - (v - yMin) / (yMax - yMin) * (h - top - bottom); };
  std::ostringstream s;
  s << std::fixed;
  s.precision(1);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" class=\"scatter\">";
  s << "<line x1=\"" << left << "\" y1=\"" << h - bottom << "\" x2=\"" << w - right << "\" y2=\"" << h - bottom << "\" stroke=\"#888\"/>";
  s << "<line x1=\"" << left << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\"" << h - bottom << "\" stroke=\"#888\"/>";
  s << "<text x=\"" << w / 2 << "\" y=\"" << h - 8 << "\" text-anchor=\"middle\">" << xLabel << "</text>";
  s << "<text x=\"14\" y=\"" << h / 2 << "\" transform=\"rotate(-90 14 " << h / 2 << ")\" text-anchor=\"middle\">" << yLabel << "</text>";
  for (int i = 0; i <= 4; ++i) {
    const double xv = xMin + (xMax - xMin) * i / 4, yv = yMin + (yMax - yMin) * i / 4;
    s << "<text x=\"" << px(xv) << "\" y=\"" << h - bottom + 14 << "\" text-anchor=\"middle\" class=\"tick\">" << xv << "</text>";
    s << "<text x=\"" << left - 6 << "\" y=\"" << py(yv) + 4 << "\" text-anchor=\"end\" class=\"tick\">" << yv << "</text>";
  }
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    // Cheapest first; of equal cost the best first, so only it can join the front.
    return points[a].cost != points[b].cost ? points[a].cost < points[b].cost : points[a].quality > points[b].quality;
  });
  std::string front;
  std::vector<bool> onFront(points.size(), false);
  double best = -1e9;
  for (size_t i : order)
    if (points[i].quality > best) {
      onFront[i] = true;
      best = points[i].quality;
      std::ostringstream p;
      p << std::fixed;
      p.precision(1);
      p << px(points[i].cost) << "," << py(points[i].quality) << " ";
      front += p.str();
    }
  s << "<polyline points=\"" << front << "\" fill=\"none\" stroke=\"#c33\" stroke-dasharray=\"4 3\"/>";
  for (size_t i = 0; i < points.size(); ++i) {
    s << "<circle cx=\"" << px(points[i].cost) << "\" cy=\"" << py(points[i].quality) << "\" r=\"4\" fill=\""
      << (points[i].highlighted ? "#c33" : "#246") << "\"><title>" << points[i].label << "</title></circle>";
    // Labels for the front (and the highlighted point) only: the rest crowd; hover shows their names.
    if (onFront[i] || points[i].highlighted)
      s << "<text x=\"" << px(points[i].cost) + 6 << "\" y=\"" << py(points[i].quality) - 6 << "\" class=\"label\">" << points[i].label << "</text>";
  }
  s << "</svg>";
  return s.str();
}

}  // namespace app
