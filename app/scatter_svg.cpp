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

namespace {

// The plot's frame: its size, margins and data ranges, and where a value lands.
struct PlotFrame {
  double w = 640, h = 380, left = 60, bottom = 62, top = 20, right = 20;
  double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
  double px(double v) const { return left + (v - xMin) / (xMax - xMin) * (w - left - right); }
  double py(double v) const { return h - bottom - (v - yMin) / (yMax - yMin) * (h - top - bottom); }
};

PlotFrame plotFrame(const std::vector<ScatterPoint>& points, const ScatterOptions& options) {
  PlotFrame f;
  for (const ScatterPoint& p : points) {
    f.xMin = std::min(f.xMin, p.cost), f.xMax = std::max(f.xMax, p.cost);
    f.yMin = std::min(f.yMin, p.quality), f.yMax = std::max(f.yMax, p.quality);
  }
  if (options.target) f.yMin = std::min(f.yMin, *options.target), f.yMax = std::max(f.yMax, *options.target);
  if (points.empty()) f.xMin = 0, f.xMax = 1, f.yMin = 0, f.yMax = 1;
  if (f.xMax <= f.xMin) f.xMax = f.xMin + 1;
  if (f.yMax <= f.yMin) f.yMax = f.yMin + 1;
  f.xMin = 0, f.yMin = std::floor(f.yMin - 1), f.yMax = std::ceil(f.yMax + 1), f.xMax *= 1.1;
  return f;
}

// Axes, their labels and ticks, and the target line.
void drawAxes(std::ostringstream& s, const PlotFrame& f, const ScatterOptions& options) {
  s << "<line x1=\"" << f.left << "\" y1=\"" << f.h - f.bottom << "\" x2=\"" << f.w - f.right << "\" y2=\""
    << f.h - f.bottom << "\" stroke=\"#888\"/>";
  s << "<line x1=\"" << f.left << "\" y1=\"" << f.top << "\" x2=\"" << f.left << "\" y2=\"" << f.h - f.bottom
    << "\" stroke=\"#888\"/>";
  s << "<text x=\"" << f.w / 2 << "\" y=\"" << f.h - f.bottom + 32 << "\" text-anchor=\"middle\">"
    << xmlEscape(options.xLabel) << "</text>";
  s << "<text x=\"14\" y=\"" << f.h / 2 << "\" transform=\"rotate(-90 14 " << f.h / 2 << ")\" text-anchor=\"middle\">"
    << xmlEscape(options.yLabel) << "</text>";
  for (int i = 0; i <= 4; ++i) {
    const double xv = f.xMin + (f.xMax - f.xMin) * i / 4, yv = f.yMin + (f.yMax - f.yMin) * i / 4;
    s << "<text x=\"" << f.px(xv) << "\" y=\"" << f.h - f.bottom + 14 << "\" text-anchor=\"middle\" class=\"tick\">"
      << xv << "</text>";
    s << "<text x=\"" << f.left - 6 << "\" y=\"" << f.py(yv) + 4 << "\" text-anchor=\"end\" class=\"tick\">" << yv
      << "</text>";
  }
  if (options.target) {
    s << "<line class=\"target\" x1=\"" << f.left << "\" y1=\"" << f.py(*options.target) << "\" x2=\"" << f.w - f.right
      << "\" y2=\"" << f.py(*options.target) << "\" stroke=\"#393\" stroke-dasharray=\"2 2\"/>";
    s << "<text x=\"" << f.w - f.right - 4 << "\" y=\"" << f.py(*options.target) - 4
      << "\" text-anchor=\"end\" fill=\"#393\">target " << *options.target << "</text>";
  }
}

// Labels, the highlighted and front points first so that they get the nearest free places: eight
// directions at growing distances; a label that had to move away gets a leader line.
void drawLabels(std::ostringstream& s, const PlotFrame& f, const std::vector<ScatterPoint>& points,
                const std::vector<bool>& onFront) {
  std::vector<Box> taken;  // points and placed labels
  for (const ScatterPoint& p : points)
    taken.push_back({f.px(p.cost) - kPointRadius, f.py(p.quality) - kPointRadius, f.px(p.cost) + kPointRadius,
                     f.py(p.quality) + kPointRadius});
  std::vector<size_t> labelOrder = costOrder(points);
  std::stable_sort(labelOrder.begin(), labelOrder.end(), [&](size_t a, size_t b) {
    return int(points[a].highlighted) * 2 + int(onFront[a]) > int(points[b].highlighted) * 2 + int(onFront[b]);
  });
  const double directions[][2] = {{1, -1}, {1, 1}, {-1, -1}, {-1, 1}, {0, -1}, {0, 1}, {1, 0}, {-1, 0}};
  for (size_t i : labelOrder) {
    const double x = f.px(points[i].cost), y = f.py(points[i].quality);
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
        if (box.x0 < f.left + 2 || box.x1 > f.w - 2 || box.y0 < 2 || box.y1 > f.h - f.bottom - 2) continue;
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
}

// The legend, under the axis label.
void drawLegend(std::ostringstream& s, const PlotFrame& f, const ScatterOptions& options) {
  const double ly = f.h - 10, left = f.left;
  s << "<g class=\"legend\"><line x1=\"" << left << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + 24 << "\" y2=\""
    << ly - 4 << "\" stroke=\"#c33\" stroke-dasharray=\"4 3\"/><text x=\"" << left + 30 << "\" y=\"" << ly
    << "\">Pareto front: no cheaper point is better</text>";
  s << "<circle cx=\"" << left + 290 << "\" cy=\"" << ly - 4 << "\" r=\"4\" fill=\"#246\"/><text x=\"" << left + 298
    << "\" y=\"" << ly << "\">a method setting</text>";
  if (!options.highlightMeaning.empty())
    s << "<circle cx=\"" << left + 420 << "\" cy=\"" << ly - 4 << "\" r=\"4\" fill=\"#c33\"/><text x=\"" << left + 428
      << "\" y=\"" << ly << "\">" << xmlEscape(options.highlightMeaning) << "</text>";
}

}  // namespace

std::string svgScatter(const std::vector<ScatterPoint>& points, const ScatterOptions& options) {
  const PlotFrame f = plotFrame(points, options);
  std::ostringstream s;
  s << std::fixed;
  s.precision(1);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << f.w << "\" height=\"" << f.h << "\" class=\"scatter\">";
  s << "<style>.scatter text{font:11px sans-serif}.tick{fill:#666}.label{fill:#246}.label.hi{fill:#c33}</style>";
  drawAxes(s, f, options);
  std::vector<bool> onFront(points.size(), false);
  std::ostringstream front;
  front << std::fixed;
  front.precision(1);
  for (size_t i : paretoFront(points)) {
    onFront[i] = true;
    front << f.px(points[i].cost) << "," << f.py(points[i].quality) << " ";
  }
  s << "<polyline class=\"front\" points=\"" << front.str()
    << "\" fill=\"none\" stroke=\"#c33\" stroke-dasharray=\"4 3\"/>";
  for (const ScatterPoint& p : points)
    s << "<circle cx=\"" << f.px(p.cost) << "\" cy=\"" << f.py(p.quality) << "\" r=\"" << kPointRadius << "\" fill=\""
      << (p.highlighted ? "#c33" : "#246") << "\"><title>" << xmlEscape(p.label) << "</title></circle>";
  drawLabels(s, f, points, onFront);
  drawLegend(s, f, options);
  s << "</g></svg>";
  return s.str();
}

}  // namespace app
