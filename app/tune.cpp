#include "tune.h"

#include "bounded_json.h"
#include "commands.h"
#include "headless_context.h"
#include "measure.h"
#include "progress.h"
#include "scatter_svg.h"
#include "scene.h"
#include "session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

namespace app {

namespace {

using nlohmann::json;

double worstFrame(const TunePoint& point, const std::string& metric) {
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& frame : point.frames) worst = std::min(worst, frame.at(metric));
  return worst;
}

}  // namespace

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

TuneTarget parseTuneTarget(const std::string& text) {
  const size_t equals = text.find('=');
  TuneTarget target;
  if (equals != std::string::npos) target.metric = text.substr(0, equals);
  const std::vector<std::string>& allowed = qualityFigures();
  if (std::find(allowed.begin(), allowed.end(), target.metric) == allowed.end())
    throw std::invalid_argument("--target '" + text + "': expected FIGURE=X with FIGURE one of " + joined(allowed));
  try {
    target.threshold = std::stod(text.substr(equals + 1));
  } catch (const std::exception&) {
    throw std::invalid_argument("--target '" + text + "': '" + text.substr(equals + 1) + "' is not a number");
  }
  return target;
}

TuneChoice chooseCheapest(const std::vector<TunePoint>& points, const std::vector<TuneTarget>& targets) {
  TuneChoice choice;
  if (points.empty() || targets.empty()) return choice;
  const std::string& primary = targets.front().metric;
  std::vector<int> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return worstFrame(points[a], primary) > worstFrame(points[b], primary);
  });
  std::vector<ScatterPoint> costAndQuality;
  for (const TunePoint& point : points) costAndQuality.push_back({"", point.cost, worstFrame(point, primary)});
  for (size_t i : paretoFront(costAndQuality)) choice.front.push_back(int(i));
  // The shortfall of a point: how far its worst frame misses the targets (0 when it meets them all).
  auto shortfall = [&](const TunePoint& p) {
    double missing = 0;
    for (const TuneTarget& t : targets) missing += std::max(0.0, t.threshold - worstFrame(p, t.metric));
    return missing;
  };
  for (int i : order)
    if (shortfall(points[i]) == 0) {
      choice.feasible = true;
      choice.chosen = i;
      break;
    }
  if (!choice.feasible) {
    choice.chosen = order.front();
    for (int i : order)
      if (shortfall(points[i]) < shortfall(points[choice.chosen])) choice.chosen = i;
    return choice;
  }
  for (int i : choice.front)
    if (points[i].cost < points[choice.chosen].cost) choice.nextCheaper = i;
  return choice;
}

namespace {

// Every candidate's figures on every frame of every scene: from the cache where it has them (keyed by
// scene, size, ground truth, frame and renderer), measured otherwise (and added to the cache).
std::vector<TunePoint> measureCandidates(const TuneOptions& options, const std::vector<std::string>& specs,
                                         json& cache) {
  host::HeadlessContext context;
  std::vector<TunePoint> points(specs.size());
  for (size_t i = 0; i < specs.size(); ++i) points[i].spec = specs[i];
  auto framesOf = [&](const host::Scene& scene) {
    return std::max(1, std::min(options.frames, scene.path.frameCount()));
  };
  int total = 0;
  for (const std::string& scenePath : options.scenes) total += framesOf(host::loadScene(scenePath)) * int(specs.size());
  Progress progress("tune", total);
  int measured = 0, reused = 0;
  for (size_t sceneIndex = 0; sceneIndex < options.scenes.size(); ++sceneIndex) {
    const std::string& scenePath = options.scenes[sceneIndex];
    Session session(scenePath, options.width, options.height, context.info().summary());
    const int frames = framesOf(session.scene);
    for (int f = 0; f < frames; ++f) {
      const int frame = f * std::max(session.scene.path.frameCount() / frames, 1);
      std::ostringstream key;
      key << scenePath << "|" << options.width << "x" << options.height << "|gt" << options.groundTruthSamples
          << "|frame" << frame << "|" << context.info().renderer;
      json& entry = cache[key.str()];
      std::optional<FrameReference> reference;
      for (size_t i = 0; i < specs.size(); ++i) {
        // An entry from before a figure existed (interior_psnr_db, say) is measured again.
        const bool cached = entry.contains(specs[i]) && entry[specs[i]].contains(options.cost) &&
                            std::all_of(qualityFigures().begin(), qualityFigures().end(),
                                        [&](const std::string& figure) { return entry[specs[i]].contains(figure); });
        if (cached) {
          ++reused;
        } else {
          if (!reference)
            reference = renderReference(session, session.camera(frame), options.groundTruthSamples, nullptr);
          session.configure(parseMethodSpec(specs[i], {}).config, specs[i]);
          entry[specs[i]] = figures(measure(session, session.camera(frame), *reference, 1, 1));
          ++measured;
        }
        progress.step("scene " + std::to_string(sceneIndex + 1) + "/" + std::to_string(options.scenes.size()) +
                      ", frame " + std::to_string(f + 1) + "/" + std::to_string(frames) + ", point " +
                      std::to_string(i + 1) + "/" + std::to_string(specs.size()) + ": " + specs[i]);
        const json& e = entry[specs[i]];
        const retroaa::Config asked = parseMethodSpec(specs[i], {}).config;
        const retroaa::MethodInfo* row = retroaa::findMethod(asked.method);
        points[i].requestedSamples = row && row->multisampled ? asked.samples : 1;
        points[i].grantedSamples = e.value("samples", points[i].requestedSamples);
        std::map<std::string, double> quality;
        for (const std::string& figure : qualityFigures())  // null: nothing to miss on this frame (no edge pixel)
          quality[figure] = e[figure].is_null() ? std::numeric_limits<double>::infinity() : e[figure].get<double>();
        points[i].frames.push_back(quality);
        points[i].cost += e[options.cost].get<double>();
      }
    }
  }
  std::fprintf(stderr, "tune: measured %d points, reused %d from %s\n", measured, reused, options.cache.c_str());
  for (TunePoint& p : points) p.cost /= double(std::max<size_t>(p.frames.size(), 1));
  return points;
}

// When the driver backed a point with another sample count than it asked for (llvmpipe gives 4 for 2),
// its figures are those of the granted count: the result must say so, not only the scrolling log.
std::string grantedNote(const TunePoint& point) {
  if (point.grantedSamples == point.requestedSamples) return "";
  return point.spec + " asked for " + std::to_string(point.requestedSamples) + " samples; this driver allocated " +
         std::to_string(point.grantedSamples) + ", so its figures are those of " +
         std::to_string(point.grantedSamples) + " samples and another driver may give other ones";
}

// The written config (a comment naming the point, then its keys), the front as SVG, the report and
// the predicted worst-frame figures.
void writeTuneOutputs(const TuneOptions& options, const std::vector<TunePoint>& points, const TuneChoice& choice,
                      const std::string& report) {
  const TunePoint& chosen = points[choice.chosen];
  const retroaa::Config config = parseMethodSpec(chosen.spec, {}).config;
  const auto parent = std::filesystem::path(options.out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  std::ofstream(options.out) << "# retroaa tune: " << chosen.spec << " (" << options.cost << " " << chosen.cost << ")\n"
                             << (grantedNote(chosen).empty() ? "" : "# " + grantedNote(chosen) + "\n")
                             << retroaa::toConfigText(config);
  const std::string& primary = options.targets.front().metric;
  std::vector<ScatterPoint> scatter;
  for (size_t i = 0; i < points.size(); ++i)
    scatter.push_back({points[i].spec, points[i].cost, worstFrame(points[i], primary), int(i) == choice.chosen});
  const std::string highlight = choice.feasible ? "chosen" : "closest (misses the target)";
  std::ofstream(options.out + ".svg") << svgScatter(
      scatter, {options.cost + " (mean)", "worst-frame " + primary, options.targets.front().threshold, highlight});
  std::ofstream(options.out + ".md") << report << "\n![front]("
                                     << std::filesystem::path(options.out).filename().string() << ".svg)\n";
  json worst = json::object();
  for (const std::string& figure : qualityFigures()) worst[figure] = worstFrame(chosen, figure);
  std::ofstream(options.out + ".json") << json{{"chosen", chosen.spec},
                                               {"cost_figure", options.cost},
                                               {"cost", chosen.cost},
                                               {"worst", worst},
                                               {"requested_samples", chosen.requestedSamples},
                                               {"granted_samples", chosen.grantedSamples}}
                                              .dump(1)
                                       << "\n";
}

}  // namespace

int runTune(const TuneOptions& options) {
  if (options.targets.empty()) throw std::invalid_argument("tune needs at least one --target (e.g. edge_psnr_db=18)");
  const std::vector<std::string>& costs = costFigures();
  if (std::find(costs.begin(), costs.end(), options.cost) == costs.end())
    throw std::invalid_argument("--cost must be one of " + joined(costs) + ", got '" + options.cost + "'");
  const std::vector<std::string> specs = expandMethodList(options.candidates.empty() ? "grid" : options.candidates);
  json cache = json::object();
  std::string problem;  // a missing, unreadable, corrupt or unbounded cache only means measuring again
  if (const std::optional<std::string> text = host::readUserTextFile(options.cache, problem)) try {
      cache = host::parseBoundedJson(*text, options.cache);
    } catch (const host::SceneError& e) {
      std::fprintf(stderr, "retroaa tune: measuring again: %s\n", e.what());
    }
  if (!cache.is_object()) cache = json::object();
  const std::vector<TunePoint> points = measureCandidates(options, specs, cache);
  const auto cacheParent = std::filesystem::path(options.cache).parent_path();
  std::filesystem::create_directories(cacheParent.empty() ? "." : cacheParent);
  std::ofstream(options.cache) << cache.dump(1) << "\n";

  const TuneChoice choice = chooseCheapest(points, options.targets);
  auto describe = [&](int i) {
    std::ostringstream s;
    s << "`" << points[i].spec << "`: " << options.cost << " " << points[i].cost;
    for (const std::string& figure : qualityFigures())
      s << ", worst " << figure << " " << worstFrame(points[i], figure);
    return s.str();
  };
  std::ostringstream report;
  report << "# retroaa tune\n\nTargets:";
  for (const TuneTarget& t : options.targets) report << " " << t.metric << " ≥ " << t.threshold;
  report << " on every frame; cost: " << options.cost << ".\n\nPareto front (cost against the worst frame of "
         << options.targets.front().metric << "):\n\n";
  const char* mark = choice.feasible ? "  ← chosen" : "  ← closest, misses the target";
  for (int i : choice.front) report << "- " << describe(i) << (i == choice.chosen ? mark : "") << "\n";
  if (!choice.feasible) {
    report << "\nNo setting meets the targets. Closest: " << describe(choice.chosen) << "\n";
    std::printf("%s", report.str().c_str());
    std::printf("tune: no setting meets the targets; the closest is %s\n", points[choice.chosen].spec.c_str());
    return kExitCheckFailed;
  }
  report << "\nChosen: " << describe(choice.chosen) << "\n";
  if (const std::string note = grantedNote(points[choice.chosen]); !note.empty()) report << "\nNote: " << note << ".\n";
  if (choice.nextCheaper >= 0)
    report << "The next cheaper point on the front, " << describe(choice.nextCheaper) << ", misses a target.\n";
  writeTuneOutputs(options, points, choice, report.str());
  std::printf("%s", report.str().c_str());
  std::printf("tune: wrote %s (%s)\n", options.out.c_str(), points[choice.chosen].spec.c_str());
  return kExitOk;
}

}  // namespace app
