// Speed-against-error scatter plots as SVG, for the regression report and the tuner.
#include "scatter_svg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace app {

namespace {

struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

constexpr double kCharWidth = 6.2, kLabelHeight = 12, kPointRadius = 4;

// Cheapest first; of equal cost the best first.
std::vector<size_t> costOrder(const std::vector<ScatterPoint>& points) {
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return points[a].cost != points[b].cost ? points[a].cost < points[b].cost : points[a].quality > points[b].quality;
  });
  return order;
}

}  // namespace

std::vector<size_t> paretoFront(const std::vector<ScatterPoint>& points) {
  std::vector<size_t> front;
  double best = -std::numeric_limits<double>::infinity();
  for (size_t i : costOrder(points))
    if (points[i].quality > best) best = points[i].quality, front.push_back(i);
  return front;
}

std::string svgScatter(const std::vector<ScatterPoint>& points, const ScatterOptions& options) {
  const double w = 640, h = 380, left = 60, bottom = 62, top = 20, right = 20;
  double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
  for (const ScatterPoint& p : points) {
    xMin = std::min(xMin, p.cost), xMax = std::max(xMax, p.cost);
    yMin = std::min(yMin, p.quality), yMax = std::max(yMax, p.quality);
  }
  if (options.target) yMin = std::min(yMin, *options.target), yMax = std::max(yMax, *options.target);
  if (points.empty()) xMin = 0, xMax = 1, yMin = 0, yMax = 1;
  if (xMax <= xMin) xMax = xMin + 1;
  if (yMax <= yMin) yMax = yMin + 1;
  xMin = 0, yMin = std::floor(yMin - 1), yMax = std::ceil(yMax + 1), xMax *= 1.1;
  auto px = [&](double v) { return left + (v - xMin) / (xMax - xMin) * (w - left - right); };
  auto py = [&](double v) { return h - bottom - (v - yMin) / (yMax - yMin) * (h - top - bottom); };
  std::ostringstream s;
  s << std::fixed;
  s.precision(1);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" class=\"scatter\">";
  s << "<style>.scatter text{font:11px sans-serif}.tick{fill:#666}.label{fill:#246}.label.hi{fill:#c33}</style>";
  s << "<line x1=\"" << left << "\" y1=\"" << h - bottom << "\" x2=\"" << w - right << "\" y2=\"" << h - bottom
    << "\" stroke=\"#888\"/>";
  s << "<line x1=\"" << left << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\"" << h - bottom
    << "\" stroke=\"#888\"/>";
  s << "<text x=\"" << w / 2 << "\" y=\"" << h - bottom + 32 << "\" text-anchor=\"middle\">"
    << xmlEscape(options.xLabel) << "</text>";
  s << "<text x=\"14\" y=\"" << h / 2 << "\" transform=\"rotate(-90 14 " << h / 2 << ")\" text-anchor=\"middle\">"
    << xmlEscape(options.yLabel) << "</text>";
  for (int i = 0; i <= 4; ++i) {
    const double xv = xMin + (xMax - xMin) * i / 4, yv = yMin + (yMax - yMin) * i / 4;
    s << "<text x=\"" << px(xv) << "\" y=\"" << h - bottom + 14 << "\" text-anchor=\"middle\" class=\"tick\">" << xv
      << "</text>";
    s << "<text x=\"" << left - 6 << "\" y=\"" << py(yv) + 4 << "\" text-anchor=\"end\" class=\"tick\">" << yv
      << "</text>";
  }
  if (options.target) {
    s << "<line class=\"target\" x1=\"" << left << "\" y1=\"" << py(*options.target) << "\" x2=\"" << w - right
      << "\" y2=\"" << py(*options.target) << "\" stroke=\"#393\" stroke-dasharray=\"2 2\"/>";
    s << "<text x=\"" << w - right - 4 << "\" y=\"" << py(*options.target) - 4
      << "\" text-anchor=\"end\" fill=\"#393\">target " << *options.target << "</text>";
  }

  std::vector<bool> onFront(points.size(), false);
  std::ostringstream front;
  front << std::fixed;
  front.precision(1);
  for (size_t i : paretoFront(points)) {
    onFront[i] = true;
    front << px(points[i].cost) << "," << py(points[i].quality) << " ";
  }
  s << "<polyline class=\"front\" points=\"" << front.str()
    << "\" fill=\"none\" stroke=\"#c33\" stroke-dasharray=\"4 3\"/>";

  std::vector<Box> taken;  // points and placed labels
  for (const ScatterPoint& p : points)
    taken.push_back({px(p.cost) - kPointRadius, py(p.quality) - kPointRadius, px(p.cost) + kPointRadius,
                     py(p.quality) + kPointRadius});
  for (const ScatterPoint& p : points)
    s << "<circle cx=\"" << px(p.cost) << "\" cy=\"" << py(p.quality) << "\" r=\"" << kPointRadius << "\" fill=\""
      << (p.highlighted ? "#c33" : "#246") << "\"><title>" << xmlEscape(p.label) << "</title></circle>";
  // Labels, the highlighted and front points first so that they get the nearest free places: eight
  // directions at growing distances; a label that had to move away gets a leader line.
  std::vector<size_t> labelOrder = costOrder(points);
  std::stable_sort(labelOrder.begin(), labelOrder.end(), [&](size_t a, size_t b) {
    return int(points[a].highlighted) * 2 + int(onFront[a]) > int(points[b].highlighted) * 2 + int(onFront[b]);
  });
  const double directions[][2] = {{1, -1}, {1, 1}, {-1, -1}, {-1, 1}, {0, -1}, {0, 1}, {1, 0}, {-1, 0}};
  for (size_t i : labelOrder) {
    const double x = px(points[i].cost), y = py(points[i].quality);
    const double width = kCharWidth * double(points[i].label.size());
    Box chosen{};
    bool found = false;
    for (int ring = 1; ring <= 10 && !found; ++ring)
      for (const auto& d : directions) {
        const double reach = 6.0 * ring;
        // Anchor the box on the side the direction points to.
        const double bx = d[0] > 0 ? x + reach : d[0] < 0 ? x - reach - width : x - width / 2;
        const double by = d[1] < 0 ? y - reach - kLabelHeight : d[1] > 0 ? y + reach : y - kLabelHeight / 2;
        const Box box{bx, by, bx + width, by + kLabelHeight};
        if (box.x0 < left + 2 || box.x1 > w - 2 || box.y0 < 2 || box.y1 > h - bottom - 2) continue;
        if (std::any_of(taken.begin(), taken.end(), [&](const Box& t) { return t.overlaps(box); })) continue;
        chosen = box, found = true;
        break;
      }
    if (!found) chosen = {x + 6, y - 6 - kLabelHeight, x + 6 + width, y - 6};  // crowded: overlap beats no label
    taken.push_back(chosen);
    const double cx = std::clamp(x, chosen.x0, chosen.x1), cy = std::clamp(y, chosen.y0, chosen.y1);
    if (std::hypot(cx - x, cy - y) > 10)
      s << "<line x1=\"" << x << "\" y1=\"" << y << "\" x2=\"" << cx << "\" y2=\"" << cy << "\" stroke=\"#aaa\"/>";
    s << "<text x=\"" << chosen.x0 << "\" y=\"" << chosen.y1 - 2 << "\" class=\"label"
      << (points[i].highlighted ? " hi" : "") << "\">" << xmlEscape(points[i].label) << "</text>";
  }

  // Legend, under the axis label.
  const double ly = h - 10;
  s << "<g class=\"legend\"><line x1=\"" << left << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + 24 << "\" y2=\""
    << ly - 4 << "\" stroke=\"#c33\" stroke-dasharray=\"4 3\"/><text x=\"" << left + 30 << "\" y=\"" << ly
    << "\">Pareto front: no cheaper point is better</text>";
  s << "<circle cx=\"" << left + 290 << "\" cy=\"" << ly - 4 << "\" r=\"4\" fill=\"#246\"/><text x=\"" << left + 298
    << "\" y=\"" << ly << "\">a method setting</text>";
  if (!options.highlightMeaning.empty())
    s << "<circle cx=\"" << left + 420 << "\" cy=\"" << ly - 4 << "\" r=\"4\" fill=\"#c33\"/><text x=\"" << left + 428
      << "\" y=\"" << ly << "\">" << xmlEscape(options.highlightMeaning) << "</text>";
  s << "</g></svg>";
  return s.str();
}

}  // namespace app
