#include "regress.h"

#include "progress.h"
#include "scatter_svg.h"

#include "bounded_json.h"
#include "commands.h"
#include "ground_truth.h"
#include "headless_context.h"
#include "image_io.h"
#include "measure.h"
#include "metrics.h"
#include "session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>

namespace app {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string sceneKey(const std::string& scene) {
  return scene == "default" ? "default" : fs::path(scene).stem().string();
}

std::string fileSafe(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return name;
}

// Per method, summed over a scene's frames.
struct MethodTotals {
  double psnr = 0, edgePsnr = 0, minEdgePsnr = 1e9, interiorPsnr = 0, psnrVsPerSample = 0, ssim = 0, maxError = 0;
  SequenceError sequence;  // flicker, and lag on the pixels whose ground truth changed (FrameReference)
  double evaluations = 0, gpuMs = 0;
  double wallMs = 0;  // of the first frame (0: not measured)
  std::map<std::string, double> passMs;
  int frames = 0, edgeFrames = 0;  // edge figures: frames whose ground truth has edges
  int interiorFrames = 0;
  double bytesPerPixel = 0;

  void add(const Measurement& m, const FrameReference& reference) {
    psnr += m.error.psnrDb;
    if (m.error.edgePixels > 0)
      edgePsnr += m.error.edgePsnrDb, minEdgePsnr = std::min(minEdgePsnr, m.error.edgePsnrDb), ++edgeFrames;
    if (m.error.interiorPixels > 0) interiorPsnr += m.error.interiorPsnrDb, ++interiorFrames;
    sequence.add(m.image, reference.truth, reference.changed);
    psnrVsPerSample += m.psnrVsPerSampleDb.value_or(0);
    ssim += m.error.ssim, maxError = std::max(maxError, m.error.maxAbsError);
    evaluations += m.stats.evaluationsPerPixel(), gpuMs += m.gpuMs;
    if (frames == 0) wallMs = m.wallMs;
    for (const auto& [name, ms] : m.passMs) passMs[name] += ms;
    bytesPerPixel = m.stats.pixels ? double(m.stats.bytesHeld) / double(m.stats.pixels) : 0.0;
    ++frames;
  }

  // Means over the frames (minimum and maximum where named so), by the names bench uses.
  json row(const std::string& method) const {
    const double n = std::max(frames, 1);
    json passes = json::object();
    for (const auto& [name, ms] : passMs) passes[name] = ms / n;
    return {{"method", method},
            {"frames", frames},
            {"evals_per_pixel", evaluations / n},
            {"gpu_ms", gpuMs / n},
            {"wall_ms", wallMs > 0 ? json(wallMs) : json(nullptr)},
            {"passes_ms", passes},
            {"plugin_bytes_per_pixel", bytesPerPixel},
            {"psnr_db", psnr / n},
            {"edge_psnr_db", edgeFrames ? json(edgePsnr / edgeFrames) : json(nullptr)},
            {"min_edge_psnr_db", edgeFrames ? json(minEdgePsnr) : json(nullptr)},
            {"interior_psnr_db", interiorFrames ? json(interiorPsnr / interiorFrames) : json(nullptr)},
            {"lag_psnr_db", sequence.lagPsnrDb() ? json(*sequence.lagPsnrDb()) : json(nullptr)},
            {"psnr_vs_per_sample_db", psnrVsPerSample / n},
            {"ssim", ssim / n},
            {"max_abs_error", maxError},
            {"flicker", sequence.flicker()}};
  }
};

// The window (w × h) holding the most ground-truth edge pixels: where the hard cases are.
std::pair<int, int> busiestWindow(const std::vector<uint8_t>& edges, int width, int height, int w, int h) {
  int best = -1, bestX = 0, bestY = 0;
  for (int y = 0; y + h <= height; y += h / 4)
    for (int x = 0; x + w <= width; x += w / 4) {
      int count = 0;
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) count += edges[size_t(y + j) * width + x + i];
      if (count > best) best = count, bestX = x, bestY = y;
    }
  return {bestX, bestY};
}

// A nearest-neighbour zoom of a window of an RGBA8 top-down image.
std::vector<uint8_t> crop(const std::vector<uint8_t>& image, int width, int x0, int y0, int w, int h, int zoom) {
  std::vector<uint8_t> out(size_t(w) * zoom * h * zoom * 4);
  for (int y = 0; y < h * zoom; ++y)
    for (int x = 0; x < w * zoom; ++x)
      std::copy_n(&image[(size_t(y0 + y / zoom) * width + x0 + x / zoom) * 4], 4, &out[(size_t(y) * w * zoom + x) * 4]);
  return out;
}

// A table cell: the number with `decimals` digits, or n/a where nothing was measured (null).
std::string cell(const json& value, int decimals) {
  if (value.is_null()) return "n/a";
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value.get<double>();
  return out.str();
}

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

// A scene's rows against its golden: what got worse beyond tolerance, and the methods it has no figures for
// yet (new in the list: a check fails on them too, so no method runs unguarded).
struct GoldenComparison {
  std::vector<std::string> worse, fresh;
};

GoldenComparison compareWithGolden(const json& golden, const json& scene) {
  GoldenComparison comparison;
  std::vector<std::string>& worse = comparison.worse;
  const json& tolerance = golden["tolerance"];
  for (const auto& row : scene["rows"]) {
    const std::string method = row["method"];
    if (!golden["methods"].contains(method)) {
      comparison.fresh.push_back(scene["scene"].get<std::string>() + " / " + method +
                                 ": no golden figures yet (run with --update-golden --methods " + method + ")");
      continue;
    }
    const json& g = golden["methods"][method];
    auto lower = [&](const char* figure, double allowed) {
      if (row[figure].is_null() || g[figure].is_null()) return;  // nothing measured (no edge pixel)
      const double now = row[figure], then = g[figure];
      if (now < then - allowed) {
        std::ostringstream m;
        m << scene["scene"].get<std::string>() << " / " << method << ": " << figure << " fell from " << then << " to "
          << now << " (tolerance " << allowed << ")";
        worse.push_back(m.str());
      }
    };
    auto higher = [&](const char* figure, double relative, double absolute) {
      const double now = row[figure], then = g[figure];
      if (now > then * (1.0 + relative) + absolute) {
        std::ostringstream m;
        m << scene["scene"].get<std::string>() << " / " << method << ": " << figure << " rose from " << then << " to "
          << now << " (tolerance +" << relative * 100 << " % + " << absolute << ")";
        worse.push_back(m.str());
      }
    };
    lower("psnr_db", tolerance["psnr_db"]);
    lower("edge_psnr_db", tolerance["edge_psnr_db"]);
    // Blur of textures shows here; goldens written before it was recorded lack it and skip the check.
    if (tolerance.contains("interior_psnr_db") && g.contains("interior_psnr_db"))
      lower("interior_psnr_db", tolerance["interior_psnr_db"]);
    higher("flicker", tolerance["flicker_relative"], tolerance["flicker_absolute"]);
    higher("evals_per_pixel", tolerance["evals_relative"], 0.0);
  }
  return comparison;
}

}  // namespace

std::vector<std::string> defaultRegressScenes(const std::string& dir) {
  return {"default", dir + "/scenes/engine.json", dir + "/scenes/space_battle.json", dir + "/scenes/fence.json",
          dir + "/scenes/heavy_lighting.json"};
}

namespace {

// The frames of each scene a run renders; loading validates every scene before any work.
std::vector<std::vector<int>> framesToRender(const std::vector<std::string>& scenes, const RegressOptions& options) {
  std::vector<std::vector<int>> frames;
  for (const std::string& scene : scenes) {
    const host::Scene loaded = host::loadScene(scene);
    std::vector<int> list;
    for (int f = 0; f < loaded.path.frameCount(); f += std::max(options.frameStride, 1)) list.push_back(f);
    if (options.maxFrames > 0 && int(list.size()) > options.maxFrames) list.resize(options.maxFrames);
    frames.push_back(list);
  }
  return frames;
}

// The first frame's images of one method: the image, its error, the hard-case crop and, for sliced
// methods, the samples per pixel. Returns their file names for the report.
json writeMethodImages(Session& session, const fs::path& sceneDir, const std::string& method, const Measurement& m,
                       const FrameReference& reference, std::pair<int, int> window, int cropW, int cropH) {
  const int w = session.renderer->width(), h = session.renderer->height();
  const std::string file = fileSafe(method);
  writeImage8((sceneDir / (file + ".png")).string(), w, h, m.display, session.metadata(method));
  writeImage8((sceneDir / (file + "-error.png")).string(), w, h, errorHeatmap(m.image, reference.truth));
  writeImage8((sceneDir / (file + "-crop.png")).string(), cropW * 4, cropH * 4,
              crop(m.display, w, window.first, window.second, cropW, cropH, 4));
  json entry = {{"image", file + ".png"}, {"error", file + "-error.png"}, {"crop", file + "-crop.png"}};
  if (m.stats.slices > 1) {
    const std::vector<uint8_t> counts = session.plugin().readSliceCounts();
    writeImage8((sceneDir / (file + "-samples.png")).string(), w, h,
                visualiseCounts("samples", counts, m.display, w, h, m.stats.samples));
    entry["samples"] = file + "-samples.png";
    entry["samples_scale"] = m.stats.samples;  // the colour key's top: blue 1 … red N evaluations
    const auto [fewest, most] = std::minmax_element(counts.begin(), counts.end());
    if (!counts.empty() && *fewest == *most) entry["samples_uniform"] = int(*fewest);
  }
  return entry;
}

// One scene: ground truth and the per-sample reference of every frame first, then one method at a
// time over all frames (configured once and warmed up, so its times are steady-state).
json regressScene(Session& session, const std::string& file, const std::vector<int>& frames,
                  const std::vector<MethodSpec>& specs, const RegressOptions& options, Progress& progress) {
  const int w = options.width, h = options.height;
  const std::string key = sceneKey(file);
  const fs::path sceneDir = fs::path(options.out) / fileSafe(key);
  fs::create_directories(sceneDir);
  std::vector<FrameReference> references;
  for (int frame : frames) {
    references.push_back(renderReference(session, session.camera(frame), options.groundTruthSamples, &options.base));
    if (session.scene.objectsMove() && frame > 0) {
      // The frame before's ground truth: the previous reference's where the run renders every frame.
      const bool previousMeasured = references.size() > 1 && frames[references.size() - 2] == frame - 1;
      if (previousMeasured)
        markChangedSince(references[references.size() - 2].truthRgba, references.back());
      else
        markChangedSince(
            host::renderGroundTruth(*session.renderer, session.camera(frame - 1), options.groundTruthSamples).display,
            references.back());
    }
    progress.step(key + " ground truth and per-sample, frame " + std::to_string(frame));
  }
  const int cropW = std::min(48, w), cropH = std::min(36, h);
  const std::pair<int, int> window = busiestWindow(references[0].edges, w, h, cropW, cropH);
  writeImage8((sceneDir / "ground-truth.png").string(), w, h, references[0].truthRgba);
  writeImage8((sceneDir / "ground-truth-crop.png").string(), cropW * 4, cropH * 4,
              crop(references[0].truthRgba, w, window.first, window.second, cropW, cropH, 4));
  json images = {{"crop_window", {window.first, window.second, cropW, cropH}}};
  json rows = json::array();
  for (const MethodSpec& spec : specs) {
    session.configure(spec.config, spec.name);
    MethodTotals totals;
    const int historyFrames = retroaa::historyFrames(spec.config);
    for (size_t fi = 0; fi < frames.size(); ++fi) {
      // A method with a history is judged as an engine would run it: the path played through
      // every frame, from historyFrames before the first measured one (its first camera held before the
      // path starts).
      if (historyFrames > 0)
        for (int f = fi == 0 ? frames[0] - historyFrames : frames[fi - 1] + 1; f < frames[fi]; ++f)
          session.renderer->renderFrame(session.camera(std::max(f, 0)));
      const Measurement m = measure(session, session.camera(frames[fi]), references[fi], 1, fi == 0 ? 1 : 0,
                                    fi == 0 ? options.wallFrames : 0);
      totals.add(m, references[fi]);
      if (fi == 0)
        images[spec.name] = writeMethodImages(session, sceneDir, spec.name, m, references[fi], window, cropW, cropH);
      progress.step(key + " " + spec.name + " frame " + std::to_string(frames[fi]));
    }
    rows.push_back(totals.row(spec.name));
  }
  addTimeRatios(rows);
  return {{"scene", key},
          {"name", session.scene.name},
          {"file", file},
          {"frames", frames.size()},
          {"directory", fileSafe(key)},
          {"images", images},
          {"rows", rows}};
}

void writeSceneHtml(std::ostringstream& html, const json& scene, int w) {
  const std::string dir = scene["directory"];
  html << "<h2>" << htmlEscape(scene["name"]) << "</h2>\n<p>" << htmlEscape(scene["file"]) << ", " << scene["frames"]
       << " frames</p>\n<table><tr><th>method</th><th>evals/px</th><th>GPU ms</th><th>wall ms (frame 1)</th><th>plugin "
          "overhead ms</th><th>plugin B/px</th><th>PSNR dB</th>"
       << "<th>edge PSNR dB</th><th>min edge PSNR</th><th>interior PSNR dB</th><th>lag PSNR dB</th><th>PSNR vs "
          "per-sample</th><th>SSIM</th><th>max "
          "err</th><th>flicker</th></tr>\n";
  for (const auto& r : scene["rows"]) {
    html << "<tr><td>" << htmlEscape(r["method"]) << "</td>";
    for (const auto& [figure, decimals] :
         std::initializer_list<std::pair<const char*, int>>{{"evals_per_pixel", 3},
                                                            {"gpu_ms", 2},
                                                            {"wall_ms", 2},
                                                            {"plugin_overhead_ms", 2},
                                                            {"plugin_bytes_per_pixel", 0},
                                                            {"psnr_db", 2},
                                                            {"edge_psnr_db", 2},
                                                            {"min_edge_psnr_db", 2},
                                                            {"interior_psnr_db", 2},
                                                            {"lag_psnr_db", 2},
                                                            {"psnr_vs_per_sample_db", 2},
                                                            {"ssim", 4},
                                                            {"max_abs_error", 3},
                                                            {"flicker", 4}})
      html << "<td>" << cell(r[figure], decimals) << "</td>";
    html << "</tr>\n";
  }
  std::vector<ScatterPoint> scatter;
  for (const auto& r : scene["rows"])
    if (!r["edge_psnr_db"].is_null())  // a scene without edge pixels has nothing to plot
      scatter.push_back({r["method"].get<std::string>(), r["gpu_ms"].get<double>(), r["edge_psnr_db"].get<double>()});
  html << "</table>\n"
       << svgScatter(scatter, {"GPU ms per frame (mean)", "edge PSNR dB", std::nullopt, ""})
       << "\n<h3>Hard-case crop (first frame, 4× nearest)</h3>\n<div>";
  for (const auto& r : scene["rows"]) {
    const std::string m = r["method"];
    html << "<figure><img src=\"" << dir << "/" << scene["images"][m]["crop"].get<std::string>() << "\" alt=\""
         << htmlEscape(m) << "\"><figcaption>" << htmlEscape(m) << "</figcaption></figure>";
  }
  html << "<figure><img src=\"" << dir
       << "/ground-truth-crop.png\" alt=\"ground truth\"><figcaption>ground truth</figcaption></figure></div>\n"
       << "<h3>First frame, error heat maps and samples per pixel</h3>\n"
       << "<p class=\"key\">Error heat map (largest channel difference from the ground truth, display values): "
          "<span class=\"ramp heat\"></span> 0 … 0.25 and above. Samples per pixel (lighting evaluations, "
          "sliced methods only): <span class=\"ramp count\"></span> 1 … the sample count.</p>\n<div>";
  for (const auto& r : scene["rows"]) {
    const std::string m = r["method"];
    const json& im = scene["images"][m];
    html << "<figure><img src=\"" << dir << "/" << im["image"].get<std::string>() << "\" width=\"" << w << "\" alt=\""
         << htmlEscape(m) << "\"><img src=\"" << dir << "/" << im["error"].get<std::string>() << "\" width=\"" << w
         << "\" alt=\"error\">";
    std::string caption = htmlEscape(m) + ": image, error";
    if (im.contains("samples")) {
      html << "<img src=\"" << dir << "/" << im["samples"].get<std::string>() << "\" width=\"" << w
           << "\" alt=\"samples\">";
      caption += ", samples per pixel (1 … " + std::to_string(im["samples_scale"].get<int>()) + ")";
      if (im.contains("samples_uniform"))  // per-sample: one colour is the whole story
        caption += "; every pixel lit " + std::to_string(im["samples_uniform"].get<int>()) + " times, so one colour";
    }
    html << "<figcaption>" << caption << "</figcaption></figure>";
  }
  html << "<figure><img src=\"" << dir << "/ground-truth.png\" width=\"" << w
       << "\" alt=\"ground truth\"><figcaption>ground truth</figcaption></figure></div>\n";
}

void writeHtml(const json& report, const RegressOptions& options) {
  std::ostringstream html;
  html
      << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>retroaa regression report</title>\n"
      << "<style>body{font-family:sans-serif;margin:24px;color:#222}table{border-collapse:collapse;margin:8px 0}"
         "td,th{border:1px solid #ccc;padding:3px "
         "8px;text-align:right}th{background:#eee}td:first-child{text-align:left}"
         "img{image-rendering:pixelated;border:1px solid "
         "#999;margin:2px}figure{display:inline-block;margin:4px;text-align:center}"
         "figcaption{font-size:12px}.scatter "
         "text{font-size:11px}.label{fill:#246}.tick{fill:#666}"
         ".ramp{display:inline-block;width:120px;height:10px;border:1px solid #999;vertical-align:middle}"
         ".heat{background:linear-gradient(to right,#000,#f00,#ff0,#fff)}"
         ".count{background:linear-gradient(to right,#00f,#0f0,#f00)}</style></head><body>\n"
      << "<h1>retroaa: speed against error on recorded demo scenes</h1>\n<p>" << htmlEscape(report["renderer"]) << "; "
      << options.width << "×" << options.height << ", ground truth " << options.groundTruthSamples << "×"
      << options.groundTruthSamples
      << " supersamples per pixel. Figures are means over each scene's frames; errors on tonemapped display values. "
      << "<b>Flicker</b> is the frame-to-frame change of the error (RMS), what players notice as crawling edges.</p>\n";
  for (const auto& scene : report["scenes"]) writeSceneHtml(html, scene, options.width);
  html << "</body></html>\n";
  std::ofstream(fs::path(options.out) / "report.html") << html.str();
}

// A golden file's JSON, or nullopt where there is none yet.
std::optional<json> readGolden(const fs::path& goldenFile) {
  std::string problem;
  const std::optional<std::string> text = host::readUserTextFile(goldenFile.string(), problem);
  if (!text) return std::nullopt;
  const json golden = host::parseBoundedJson(*text, goldenFile.string());
  if (!golden.is_object()) throw std::invalid_argument(goldenFile.string() + ": not a golden file (not a JSON object)");
  return golden;
}

// Goldens: the quality figures per scene and method, with tolerances. An update replaces the figures of the
// methods run and keeps the others' where the settings match. Returns the exit status.
int updateAndCheckGoldens(const json& report, const RegressOptions& options) {
  int status = kExitOk;
  size_t worseCount = 0, freshCount = 0;
  const fs::path goldenDirectory = options.goldenDirectory.empty() ? fs::path(RETROAA_INTEGRATION_TESTS_DIR) / "golden"
                                                                   : fs::path(options.goldenDirectory);
  for (const auto& scene : report["scenes"]) {
    const fs::path goldenFile =
        goldenDirectory / (fileSafe(scene["scene"]) + (options.host == "fso" ? "" : "." + options.host) + ".json");
    const json settings = {{"width", options.width},
                           {"height", options.height},
                           {"ground_truth_samples_per_axis", options.groundTruthSamples},
                           {"frames", scene["frames"]},
                           {"frame_stride", options.frameStride}};
    if (options.updateGolden) {
      const std::optional<json> existing = readGolden(goldenFile);
      json golden = {{"scene", scene["scene"]},
                     {"settings", settings},
                     {"renderer", report["renderer"]},
                     {"tolerance",
                      {{"psnr_db", 0.5},
                       {"edge_psnr_db", 0.5},
                       {"interior_psnr_db", 0.5},
                       {"flicker_relative", 0.25},
                       {"flicker_absolute", 0.0005},
                       {"evals_relative", 0.05}}},
                     {"methods", existing && (*existing)["settings"] == settings && existing->contains("methods")
                                     ? (*existing)["methods"]
                                     : json::object()}};
      for (const auto& r : scene["rows"])
        golden["methods"][r["method"].get<std::string>()] = {{"psnr_db", r["psnr_db"]},
                                                             {"edge_psnr_db", r["edge_psnr_db"]},
                                                             {"interior_psnr_db", r["interior_psnr_db"]},
                                                             {"flicker", r["flicker"]},
                                                             {"evals_per_pixel", r["evals_per_pixel"]}};
      fs::create_directories(goldenDirectory);
      std::ofstream(goldenFile) << golden.dump(2) << "\n";
      std::printf("golden written: %s\n", goldenFile.string().c_str());
    }
    if (!options.check) continue;
    const std::optional<json> golden = readGolden(goldenFile);
    if (!golden)
      throw std::invalid_argument(goldenFile.string() + ": no golden for scene '" + scene["scene"].get<std::string>() +
                                  "' (run with --update-golden)");
    if ((*golden)["settings"] != settings)
      throw std::invalid_argument(goldenFile.string() + ": golden was made with settings " +
                                  (*golden)["settings"].dump() + ", this run uses " + settings.dump());
    const GoldenComparison comparison = compareWithGolden(*golden, scene);
    for (const std::string& line : comparison.worse) std::printf("WORSE: %s\n", line.c_str());
    for (const std::string& line : comparison.fresh) std::printf("NEW: %s\n", line.c_str());
    worseCount += comparison.worse.size(), freshCount += comparison.fresh.size();
  }
  if (options.check && worseCount + freshCount > 0) status = kExitCheckFailed;
  if (options.check && status == kExitOk) std::printf("check: every figure within tolerance\n");
  if (options.check && status != kExitOk)
    std::printf("check: %zu figures got worse, %zu methods have no golden figures yet\n", worseCount, freshCount);
  return status;
}

}  // namespace

int runRegress(const RegressOptions& options) {
  const std::vector<MethodSpec> specs = parseMethodList(options.methods, options.base);
  const std::vector<std::string> scenes =
      options.scenes.empty() ? defaultRegressScenes(RETROAA_INTEGRATION_TESTS_DIR) : options.scenes;
  const std::vector<std::vector<int>> frames = framesToRender(scenes, options);
  int total = 0;
  for (const std::vector<int>& list : frames) total += int(list.size());
  host::HeadlessContext context;
  Progress progress("regress", total * (int(specs.size()) + 1));  // + each frame's references
  fs::create_directories(options.out);
  json report = {
      {"renderer", context.info().summary()},
      {"host", options.host},
      {"width", options.width},
      {"height", options.height},
      {"ground_truth_samples_per_pixel", options.groundTruthSamples * options.groundTruthSamples},
      {"metric_space", "display (tonemapped sRGB, 8-bit) values in [0,1]"},
      {"flicker", "mean over frames t of the RMS over pixels of (error_t - error_(t-1)), error = image - ground truth"},
      {"scenes", json::array()}};
  std::vector<retroaa::Config> configs;
  for (const MethodSpec& spec : specs) configs.push_back(spec.config);
  for (size_t si = 0; si < scenes.size(); ++si) {
    Session session(scenes[si], options.width, options.height, context.info().summary(), options.host, configs);
    report["scenes"].push_back(regressScene(session, scenes[si], frames[si], specs, options, progress));
  }
  std::ofstream(fs::path(options.out) / "report.json") << report.dump(2) << "\n";
  writeHtml(report, options);
  std::printf("report: %s (JSON: %s)\n", (fs::path(options.out) / "report.html").string().c_str(),
              (fs::path(options.out) / "report.json").string().c_str());
  return updateAndCheckGoldens(report, options);
}

}  // namespace app
