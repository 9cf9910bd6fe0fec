#include "tune.h"

#include "commands.h"
#include "ground_truth.h"
#include "metrics.h"
#include "scatter_svg.h"
#include "session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
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

TuneTarget parseTuneTarget(const std::string& text) {
  const size_t equals = text.find('=');
  TuneTarget target;
  if (equals != std::string::npos) target.metric = text.substr(0, equals);
  if (target.metric != "psnr" && target.metric != "edge_psnr" && target.metric != "ssim")
    throw std::invalid_argument("--target '" + text + "': expected psnr=X, edge_psnr=X or ssim=X");
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
  double best = -std::numeric_limits<double>::infinity();
  for (int i : order)
    if (worstFrame(points[i], primary) > best) best = worstFrame(points[i], primary), choice.front.push_back(i);
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

int runTune(const TuneOptions& options) {
  if (options.targets.empty()) throw std::invalid_argument("tune needs at least one --target (e.g. edge_psnr=35)");
  if (options.cost != "evals" && options.cost != "gpu_ms" && options.cost != "memory")
    throw std::invalid_argument("--cost must be evals, gpu_ms or memory, got '" + options.cost + "'");
  const std::vector<std::string> specs = expandMethodList(options.candidates.empty() ? "grid" : options.candidates);
  json cache = json::object();
  if (std::ifstream in(options.cache); in) cache = json::parse(in, nullptr, false);
  if (cache.is_discarded()) cache = json::object();

  host::HeadlessContext context;
  std::vector<TunePoint> points(specs.size());
  for (size_t i = 0; i < specs.size(); ++i) points[i].spec = specs[i];
  int measured = 0, reused = 0;
  for (const std::string& scenePath : options.scenes) {
    Session session(context, scenePath, options.width, options.height);
    const int frames = std::max(1, std::min(options.frames, session.scene.path.frameCount()));
    for (int f = 0; f < frames; ++f) {
      const int frame = f * std::max(session.scene.path.frameCount() / frames, 1);
      std::ostringstream key;
      key << scenePath << "|" << options.width << "x" << options.height << "|gt" << options.groundTruthSamples << "|frame" << frame
          << "|" << context.info().renderer;
      json& entry = cache[key.str()];
      std::unique_ptr<host::GroundTruth> truth;
      for (size_t i = 0; i < specs.size(); ++i) {
        if (!entry.contains(specs[i])) {
          if (!truth) truth = std::make_unique<host::GroundTruth>(host::renderGroundTruth(*session.renderer, session.camera(frame), options.groundTruthSamples));
          session.configure(parseMethodSpec(specs[i], {}).config);
          session.renderer->measureTime = true;
          session.renderer->renderFrame(session.camera(frame));  // warm-up
          session.renderer->renderFrame(session.camera(frame));
          session.renderer->measureTime = false;
          const retroaa::Stats stats = session.hooks->plugin().stats();
          const DisplayImage image = DisplayImage::fromRgba8(options.width, options.height, session.renderer->readDisplay());
          const ErrorMetrics m = compare(image, DisplayImage::fromRgba8(options.width, options.height, truth->display),
                                         edgeMaskFromSpread(truth->lumaStdDev));
          entry[specs[i]] = {{"psnr", m.psnrDb}, {"edge_psnr", m.edgePsnrDb}, {"ssim", m.ssim}, {"evals", stats.evaluationsPerPixel()},
                             {"gpu_ms", session.renderer->timings().frameMs},
                             {"memory", double(stats.bytesHeld) / (double(options.width) * options.height)}};
          ++measured;
          std::fprintf(stderr, "\rtune: measured %d points (%d reused)   ", measured, reused);
        } else {
          ++reused;
        }
        const json& e = entry[specs[i]];
        points[i].frames.push_back({{"psnr", e["psnr"]}, {"edge_psnr", e["edge_psnr"]}, {"ssim", e["ssim"]}});
        points[i].cost += e[options.cost].get<double>();
      }
    }
  }
  std::fprintf(stderr, "\rtune: measured %d points, reused %d from %s\n", measured, reused, options.cache.c_str());
  for (TunePoint& p : points) p.cost /= double(std::max<size_t>(p.frames.size(), 1));
  std::filesystem::create_directories(std::filesystem::path(options.cache).parent_path().empty() ? "." : std::filesystem::path(options.cache).parent_path());
  std::ofstream(options.cache) << cache.dump(1) << "\n";

  const TuneChoice choice = chooseCheapest(points, options.targets);
  auto describe = [&](int i) {
    std::ostringstream s;
    s << "`" << points[i].spec << "`: " << options.cost << " " << points[i].cost;
    for (const char* m : {"psnr", "edge_psnr", "ssim"}) s << ", worst " << m << " " << worstFrame(points[i], m);
    return s.str();
  };
  std::ostringstream report;
  report << "# retroaa tune\n\nTargets:";
  for (const TuneTarget& t : options.targets) report << " " << t.metric << " ≥ " << t.threshold;
  report << " on every frame; cost: " << options.cost << ".\n\nPareto front (cost against the worst frame of " << options.targets.front().metric << "):\n\n";
  for (int i : choice.front) report << "- " << describe(i) << (i == choice.chosen ? "  ← chosen" : "") << "\n";
  if (!choice.feasible) {
    report << "\nNo setting meets the targets. Closest: " << describe(choice.chosen) << "\n";
    std::printf("%s", report.str().c_str());
    std::printf("tune: no setting meets the targets; the closest is %s\n", points[choice.chosen].spec.c_str());
    return kExitCheckFailed;
  }
  report << "\nChosen: " << describe(choice.chosen) << "\n";
  if (choice.nextCheaper >= 0) report << "The next cheaper point on the front, " << describe(choice.nextCheaper) << ", misses a target.\n";
  const retroaa::Config config = parseMethodSpec(points[choice.chosen].spec, {}).config;
  const auto parent = std::filesystem::path(options.out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  std::ofstream(options.out) << "# retroaa tune: " << points[choice.chosen].spec << " (" << options.cost << " " << points[choice.chosen].cost << ")\n"
                             << retroaa::toConfigText(config);
  std::vector<ScatterPoint> scatter;
  for (size_t i = 0; i < points.size(); ++i)
    scatter.push_back({points[i].spec, points[i].cost, worstFrame(points[i], options.targets.front().metric), int(i) == choice.chosen});
  std::ofstream(options.out + ".svg") << svgScatter(scatter, options.cost + " (mean)", "worst-frame " + options.targets.front().metric);
  report << "\n![front](" << std::filesystem::path(options.out).filename().string() << ".svg)\n";
  std::ofstream(options.out + ".md") << report.str();
  std::ofstream(options.out + ".json") << json{{"chosen", points[choice.chosen].spec}, {"cost", points[choice.chosen].cost},
                                               {"worst", {{"psnr", worstFrame(points[choice.chosen], "psnr")},
                                                          {"edge_psnr", worstFrame(points[choice.chosen], "edge_psnr")},
                                                          {"ssim", worstFrame(points[choice.chosen], "ssim")}}}}.dump(1) << "\n";
  std::printf("%s", report.str().c_str());
  std::printf("tune: wrote %s (%s)\n", options.out.c_str(), points[choice.chosen].spec.c_str());
  return kExitOk;
}

}  // namespace app
