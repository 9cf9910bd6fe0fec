#include "commands.h"

#include "ground_truth.h"
#include "headless_context.h"
#include "image_io.h"
#include "measure.h"
#include "metrics.h"
#include "progress.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"
#include "session.h"

#include <nlohmann/json.hpp>

#include <malloc.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

namespace app {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void ensureParent(const std::string& path) {
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
}

}  // namespace

std::vector<uint8_t> visualiseCounts(const std::string& view, const std::vector<uint8_t>& countsBottomUp,
                                     const std::vector<uint8_t>& displayTopDown, int width, int height, int maxCount) {
  std::vector<uint8_t> out(size_t(width) * height * 4, 255);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t top = size_t(y) * width + x;
      const int count = countsBottomUp[size_t(height - 1 - y) * width + x];
      uint8_t* p = &out[top * 4];
      if (view == "edges") {
        for (int c = 0; c < 3; ++c) p[c] = uint8_t(displayTopDown[top * 4 + c] * 0.35f);
        if (count > 1) p[0] = 255, p[1] = 0, p[2] = 255;
      } else {
        // samples / aggregates: the count 1 … maxCount, blue → green → red
        const float t = maxCount > 1 ? std::min(float(count - 1) / float(maxCount - 1), 1.0f) : 0.0f;
        p[0] = uint8_t(255 * std::clamp(2.0f * t - 1.0f, 0.0f, 1.0f));
        p[1] = uint8_t(255 * (1.0f - std::fabs(2.0f * t - 1.0f)));
        p[2] = uint8_t(255 * std::clamp(1.0f - 2.0f * t, 0.0f, 1.0f));
      }
    }
  return out;
}

MethodSpec parseMethodSpec(const std::string& spec, const retroaa::Config& base) {
  MethodSpec out{spec, base};
  if (const retroaa::Status status = retroaa::applyMethodSpec(out.config, spec); !status)
    throw std::invalid_argument(status.error().message);
  return out;
}

ToolSpecs toolSpecs(const retroaa::MethodInfo& method) {
  // Methods with more to measure than their plain name; the rest are swept, regressed and tuned as it.
  static const std::map<std::string, ToolSpecs> kVariants = {
      {"fxaa", {"fxaa", "fxaa", "fxaa@fxaa_quality=low,fxaa"}},
      {"smaa",
       {"smaa,resolve+smaa", "smaa", "smaa@smaa_quality=low,smaa@smaa_quality=medium,smaa,smaa@smaa_quality=ultra"}},
      {"resolve",
       {"resolve,resolve/front,resolve/back,resolve/fso,resolve/window,resolve/mean,resolve+fxaa", "resolve",
        "resolve@samples=2,resolve,resolve@samples=8,resolve/fso,resolve/window,resolve+fxaa,resolve+coverage"}},
      {"coverage", {"coverage,resolve+coverage", "resolve+coverage", "coverage"}},
      {"reconstruct",
       {"reconstruct,resolve+reconstruct", "reconstruct",
        "reconstruct@samples=2,reconstruct,reconstruct@samples=8,resolve+reconstruct"}},
      // The tuner leaves temporal out: it judges single frames, where a history converged on a still
      // camera wins, and a preset must not depend on the host's jitter line (docs/methods/temporal.md).
      {"temporal", {"temporal,resolve+temporal,reconstruct+temporal", "temporal", ""}},
      {"edge", {"edge", "edge", "edge@samples=2,edge,edge@samples=8,edge@edge_detector=plane"}},
      {"adaptive",
       {"adaptive", "adaptive", "adaptive@adaptive_shading_scale=0.5,adaptive,adaptive@adaptive_shading_scale=8"}},
      {"aggregate", {"aggregate", "aggregate", "aggregate@aggregate_count=1,aggregate,aggregate@aggregate_count=3"}},
      {"smaa-s2x", {"smaa-s2x", "smaa-s2x", "smaa-s2x@smaa_quality=medium,smaa-s2x"}},
      {"per-sample", {"per-sample", "per-sample", "per-sample@samples=2,per-sample,per-sample@samples=8"}},
      // At m² lights per pixel it is a reference, not a setting: regression runs and the tuner leave it out.
      {"ssaa", {"ssaa@supersample=2", "", ""}},
  };
  const auto found = kVariants.find(method.name);
  return found != kVariants.end() ? found->second : ToolSpecs{method.name, method.name, method.name};
}

std::vector<std::string> expandMethodList(const std::string& list) {
  std::vector<std::string> out;
  auto add = [&out](const std::string& items) {
    std::stringstream in(items);
    for (std::string item; std::getline(in, item, ',');)
      if (!item.empty()) out.push_back(item);
  };
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    if (item == "all" || item == "each" || item == "grid")
      for (const retroaa::MethodInfo& row : retroaa::methodTable()) {
        const ToolSpecs tools = toolSpecs(row);
        add(item == "all" ? tools.sweep : item == "each" ? tools.regress : tools.tune);
      }
    else
      add(item);
  }
  return out;
}

std::vector<MethodSpec> parseMethodList(const std::string& list, const retroaa::Config& base) {
  std::vector<MethodSpec> specs;
  for (const std::string& name : expandMethodList(list)) specs.push_back(parseMethodSpec(name, base));
  if (specs.empty()) throw std::invalid_argument("--methods names no method");
  return specs;
}

int runRender(const RenderOptions& options) {
  host::HeadlessContext context;
  const bool groundTruth = options.method == "ground-truth";
  const retroaa::Config config =
      groundTruth || options.method.empty() ? options.base : parseMethodSpec(options.method, options.base).config;
  Session session(options.scene, options.width, options.height, context.info().summary(), options.host,
                  {groundTruth ? retroaa::Config{} : config});
  const host::Camera camera = session.camera(options.frame);
  const std::string ext = lowerExtension(options.out);
  if (ext != ".png" && ext != ".exr")
    throw std::invalid_argument("--out must end in .png or .exr, got '" + options.out + "'");
  ensureParent(options.out);

  std::vector<uint8_t> display;
  std::vector<float> radiance;
  if (groundTruth) {
    const host::GroundTruth truth = host::renderGroundTruth(*session.renderer, camera, options.groundTruthSamples);
    display = truth.display;
    radiance = truth.radiance;
  } else {
    session.configure(config);
    // A history (temporal) builds over frames: a path frame is reached by playing the path up to it (its
    // first camera held before it starts), the scene's camera by holding it still.
    const int historyFrames = retroaa::historyFrames(session.config);
    if (historyFrames > 0)
      std::fprintf(stderr, "render: %d frames accumulated first (%s)\n", historyFrames,
                   options.frame < 0 ? "a still camera" : "the path up to this frame");
    for (int i = historyFrames; i > 0; --i)
      session.renderer->renderFrame(options.frame < 0 ? camera : session.camera(std::max(options.frame - i, 0)));
    session.renderer->renderFrame(camera);
    display = session.renderer->readDisplay();
    radiance = session.renderer->readLight();
  }
  const std::string methodName =
      options.method.empty() ? retroaa::toString(session.plugin().config().method) : options.method;
  auto meta = session.metadata(methodName);
  if (!options.show.empty()) {
    if (options.show != "edges" && options.show != "samples" && options.show != "aggregates")
      throw std::invalid_argument("--show must be edges, samples or aggregates, got '" + options.show + "'");
    const retroaa::Stats stats = session.plugin().waitForStats();  // the CLI may wait: not a frame path
    if (stats.slices <= 1)  // every pixel lit once: there is nothing to show, only a blank picture
      throw std::invalid_argument("--show " + options.show +
                                  " needs a method that lights some pixels more than once; " + methodName +
                                  " lights every pixel once (" + std::to_string(stats.slices) + " slice)");
    display = visualiseCounts(options.show, session.plugin().readSliceCounts(), display, options.width, options.height,
                              std::max(stats.samples, 1));
    std::printf("%s: %.3f lighting evaluations per pixel\n", options.show.c_str(), stats.evaluationsPerPixel());
  }
  if (ext == ".exr")
    writeImageFloat(options.out, options.width, options.height, radiance, meta);
  else
    writeImage8(options.out, options.width, options.height, display, meta);

  if (!options.heatmap.empty()) {
    const host::GroundTruth truth = host::renderGroundTruth(*session.renderer, camera, options.groundTruthSamples);
    const DisplayImage image = DisplayImage::fromRgba8(options.width, options.height, display);
    const DisplayImage reference = DisplayImage::fromRgba8(options.width, options.height, truth.display);
    ensureParent(options.heatmap);
    writeImage8(options.heatmap, options.width, options.height, errorHeatmap(image, reference), meta);
    const ErrorMetrics m = compare(image, reference, edgeMaskFromSpread(truth.lumaStdDev));
    std::printf("%s vs ground truth (%dx%d): PSNR %.2f dB, edge PSNR %.2f dB, SSIM %.4f\n", methodName.c_str(),
                options.groundTruthSamples, options.groundTruthSamples, m.psnrDb, m.edgePsnrDb, m.ssim);
  }
  std::printf("wrote %s (%s)\n", options.out.c_str(), session.contextSummary.c_str());
  return kExitOk;
}

namespace {

using nlohmann::json;

std::string imageFileStem(std::string methodName) {
  std::replace(methodName.begin(), methodName.end(), '/', '-');
  return methodName;
}

// The bench table, for the terminal and the Markdown report.
std::string benchTable(const json& rows) {
  std::ostringstream table;
  table << "| method | samples | evals/px | GPU ms | time vs off | time vs per-sample | wall ms | wall vs off | plugin "
           "overhead ms | plugin B/px | PSNR dB | edge PSNR dB | model-edge PSNR dB | background-edge PSNR dB | "
           "interior PSNR dB | SSIM | max err | PSNR vs per-sample |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  // Null is "-" for a ratio whose baseline was not run, "n/a" for a figure with nothing to measure.
  auto twoDecimals = [](const json& value, const char* whenNull) {
    if (value.is_null()) return std::string(whenNull);
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << value.get<double>();
    return s.str();
  };
  auto ratio = [&](const json& value) { return twoDecimals(value, "-"); };
  auto decibels = [&](const json& value) { return twoDecimals(value, "n/a"); };
  for (const auto& row : rows) {
    table << std::fixed << "| " << row["method"].get<std::string>() << " | " << row["samples"].get<int>() << " | "
          << std::setprecision(3) << row["evals_per_pixel"].get<double>() << " | " << std::setprecision(2)
          << row["gpu_ms"].get<double>() << " | " << ratio(row["time_vs_off"]) << " | "
          << ratio(row["time_vs_per_sample"]) << " | " << ratio(row["wall_ms"]) << " | " << ratio(row["wall_vs_off"])
          << " | " << ratio(row["plugin_overhead_ms"]) << " | " << std::setprecision(1)
          << row["plugin_bytes_per_pixel"].get<double>() << " | " << std::setprecision(2)
          << row["psnr_db"].get<double>() << " | " << decibels(row["edge_psnr_db"]) << " | "
          << decibels(row["model_edge_psnr_db"]) << " | " << decibels(row["background_edge_psnr_db"]) << " | "
          << decibels(row["interior_psnr_db"]) << " | " << std::setprecision(4) << row["ssim"].get<double>() << " | "
          << std::setprecision(3) << row["max_abs_error"].get<double>() << " | " << std::setprecision(2)
          << row["psnr_vs_per_sample_db"].get<double>() << " |\n";
  }
  return table.str();
}

// Each method's plugin passes against their floors (measure_pass_floors), and the plugin's own share of off's
// frame: what a pass costs beyond the bytes it must move on this device.
std::string floorTable(const json& rows) {
  std::ostringstream table;
  table
      << "Plugin passes against their floors (a pass of the same shape that only moves the same bytes, timed in "
         "the same run; the host's lighting has none):\n\n"
      << "| passes of | own passes ms | own vs off's frame | pass | ms | floor ms | x floor | floor MB | fragments |\n"
      << "|---|---|---|---|---|---|---|---|---|\n"
      << std::fixed;
  for (const auto& row : rows) {
    const json& passes = row["passes_ms"];
    bool first = true;
    for (const auto& [pass, ms] : passes.items()) {
      if (pass.rfind("plugin.", 0) != 0) continue;
      table << "| ";
      if (first) {
        table << row["method"].get<std::string>() << " | " << std::setprecision(2) << row["plugin_own_ms"].get<double>()
              << " | "
              << (row["plugin_own_vs_off_frame"].is_null()
                      ? std::string("-")
                      : std::to_string(row["plugin_own_vs_off_frame"].get<double>()).substr(0, 4))
              << " | ";
      } else {
        table << " | | ";
      }
      first = false;
      table << pass.substr(7) << " | " << std::setprecision(2) << ms.get<double>() << " | ";
      const json& floorMs = row["passes_floor_ms"];
      const json& unmeasured = row["passes_floor_unmeasured"];
      if (floorMs.contains(pass)) {
        table << floorMs[pass].get<double>() << " | " << row["passes_floor_ratio"].value(pass, 0.0) << " | "
              << std::setprecision(3) << row["passes_floor_bytes"].value(pass, uint64_t(0)) / 1e6 << " | ";
      } else {
        table << "unmeasured: "
              << (unmeasured.contains(pass) ? unmeasured[pass].get<std::string>() : std::string("not asked for"))
              << " | - | - | ";
      }
      table << row["passes_fragment_invocations"].value(pass, uint64_t(0)) << " |\n";
    }
  }
  return table.str();
}

void writeBenchCsv(const std::string& path, const json& rows) {
  ensureParent(path);
  std::ofstream csv(path);
  const std::vector<std::string> columns = {"method",
                                            "samples",
                                            "evals_per_pixel",
                                            "gpu_ms",
                                            "time_vs_off",
                                            "time_vs_per_sample",
                                            "wall_ms",
                                            "wall_vs_off",
                                            "plugin_overhead_ms",
                                            "plugin_bytes_per_pixel",
                                            "psnr_db",
                                            "edge_psnr_db",
                                            "interior_psnr_db",
                                            "ssim",
                                            "max_abs_error",
                                            "psnr_vs_per_sample_db"};
  for (size_t c = 0; c < columns.size(); ++c) csv << columns[c] << (c + 1 == columns.size() ? "\n" : ",");
  for (const auto& row : rows)
    for (size_t c = 0; c < columns.size(); ++c) {
      const json& value = row[columns[c]];
      csv << (value.is_string() ? value.get<std::string>() : value.dump()) << (c + 1 == columns.size() ? "\n" : ",");
    }
}

void writeBenchReport(const BenchOptions& options, const json& document, const std::string& table) {
  ensureParent(options.report);
  std::ofstream md(options.report);
  md << "# retroaa speed vs error: " << document["scene"].get<std::string>() << "\n\n"
     << "Renderer: " << document["renderer_summary"].get<std::string>() << "  \n"
     << "Size " << options.width << "x" << options.height << ", ground truth " << options.groundTruthSamples << "x"
     << options.groundTruthSamples << " supersamples per pixel lit per sample (box filter on linear radiance), "
     << document["edge_pixels"]
     << " edge pixels. Errors on tonemapped display values in [0,1]; GPU times are the median of " << options.repeats
     << " frames (GPU timer queries); wall ms is the wall clock per frame over " << options.wallFrames
     << " back-to-back frames with every statistic off.\n\n"
     << table << "\n";
  if (options.imagesDirectory.empty()) return;
  const auto relative =
      std::filesystem::relative(options.imagesDirectory, std::filesystem::path(options.report).parent_path()).string();
  md << "Ground truth: ![](" << relative << "/ground-truth.png) edge mask: ![](" << relative << "/edge-mask.png)\n\n";
  for (const auto& row : document["rows"]) {
    const std::string name = row["method"].get<std::string>(), file = imageFileStem(name);
    md << "`" << name << "`: ![](" << relative << "/" << file << ".png) error: ![](" << relative << "/" << file
       << "-error.png)\n\n";
  }
}

void writeReferenceImages(const std::string& directory, const Session& session, const FrameReference& reference) {
  const int w = session.renderer->width(), h = session.renderer->height();
  std::filesystem::create_directories(directory);
  writeImage8(directory + "/ground-truth.png", w, h, reference.truthRgba, session.metadata("ground-truth"));
  // White: the models' edges; blue: those only the background's own detail (stars) makes.
  std::vector<uint8_t> mask(size_t(w) * h * 4, 255);
  for (size_t p = 0; p < reference.edges.size(); ++p) {
    const bool background = !reference.backgroundEdges.empty() && reference.backgroundEdges[p];
    mask[p * 4] = mask[p * 4 + 1] = reference.edges[p] && !background ? 255 : 0;
    mask[p * 4 + 2] = reference.edges[p] ? 255 : 0;
  }
  writeImage8(directory + "/edge-mask.png", w, h, mask);
}

}  // namespace

std::string sliceTable(const nlohmann::json& rows, const std::string& nameKey, const std::string& passPrefix) {
  using json = nlohmann::json;
  std::ostringstream table;
  table << std::fixed << std::setprecision(2);
  const std::string lightingPass = passPrefix + "slices.lighting";
  bool any = false;
  for (const auto& row : rows) {
    const json& runs = row.at("passes_ms_by_run");
    if (!runs.contains(lightingPass)) continue;
    if (!any)
      table << "Each slice's pixels lit and GPU ms (the host's lighting, the plugin's write and composite):\n\n"
            << "| method | slice | pixels lit | lighting ms | write ms | composite ms |\n|---|---|---|---|---|---|\n";
    any = true;
    const json& lighting = runs[lightingPass];
    const json& pixels = row.at("lighting_evaluations_by_slice");
    for (size_t slice = 0; slice < lighting.size(); ++slice) {
      auto cell = [&](const char* pass) {
        const std::string name = passPrefix + pass;
        return runs.contains(name) && slice < runs[name].size() ? runs[name][slice].get<double>() : 0.0;
      };
      table << "| " << (slice == 0 ? row[nameKey].get<std::string>() : "") << " | " << slice << " | "
            << (slice < pixels.size() ? std::to_string(pixels[slice].get<uint64_t>()) : "-") << " | "
            << lighting[slice].get<double>() << " | " << cell("slices.write") << " | " << cell("slices.composite")
            << " |\n";
    }
  }
  return any ? "\n" + table.str() : "";
}

int runBench(const BenchOptions& options) {
  const std::vector<MethodSpec> specs = parseMethodList(options.methods, options.base);

  host::HeadlessContext context;
  std::vector<retroaa::Config> configs;
  for (const MethodSpec& spec : specs) configs.push_back(spec.config);
  Session session(options.scene, options.width, options.height, context.info().summary(), options.host, configs);
  const host::Camera camera = session.camera(options.frame);
  const int w = options.width, h = options.height;
  std::fprintf(stderr, "bench: %s, %dx%d, %zu triangles, %zu lights; ground truth %dx%d per pixel...\n",
               session.scene.name.c_str(), w, h, session.scene.triangleCount(), session.scene.lights.size(),
               options.groundTruthSamples, options.groundTruthSamples);
  // Each method's time is roughly the same few frames: the ETA after the reference is a fair guess.
  Progress progress("bench", int(specs.size()) + 2);
  const FrameReference reference = renderReference(session, camera, options.groundTruthSamples, &options.base);
  progress.step("ground truth and per-sample reference");
  session.configure(options.base);
  const double shadingFloor = measureShadingFloor(session, camera);
  progress.step("shading floor");
  if (!options.imagesDirectory.empty()) writeReferenceImages(options.imagesDirectory, session, reference);

  json rows = json::array();
  for (const MethodSpec& spec : specs) {
    session.configure(spec.config, spec.name);
    // A history (temporal): how it converges on this still frame, then measured converged.
    std::optional<Convergence> convergence;
    if (const int frames = retroaa::historyFrames(spec.config); frames > 0)
      convergence = measureConvergence(session, camera, reference, 2 * frames, spec.config.temporalJitterLength);
    const Measurement m = measure(session, camera, reference, options.repeats, 1, options.wallFrames,
                                  options.floorFrames < 0 ? options.repeats : options.floorFrames);
    json row = figures(m);
    row["method"] = spec.name;
    if (convergence) {
      row["converged_psnr_db"] = convergence->convergedPsnrDb;
      row["frames_to_within_1db"] = convergence->framesToWithinOneDb;
      row["psnr_db_by_frame"] = convergence->psnrDb;
      std::fprintf(stderr, "%sbench: %s converges to %.2f dB on this still frame, within 1 dB of it from frame %d\n",
                   isatty(2) ? "\r\033[K" : "", spec.name.c_str(), convergence->convergedPsnrDb,
                   convergence->framesToWithinOneDb);
    }
    rows.push_back(row);
    if (!options.imagesDirectory.empty()) {
      const std::string stem = options.imagesDirectory + "/" + imageFileStem(spec.name);
      writeImage8(stem + ".png", w, h, m.display, session.metadata(spec.name));
      writeImage8(stem + "-error.png", w, h, errorHeatmap(m.image, reference.truth));
    }
    progress.step(spec.name);
  }
  addTimeRatios(rows);
  addFloorRatios(rows);
  const double copyGigabytesPerSecond = measureCopyGigabytesPerSecond();
  for (json& row : rows)  // the floor is the base sample count's; a row at another count is compared all the same
    row["evals_vs_shading_floor"] = row["evals_per_pixel"].get<double>() / shadingFloor;
  addTrafficBounds(rows, copyGigabytesPerSecond);
  const host::ContextInfo& info = context.info();
  const json document = {{"scene", session.scene.name},
                         {"width", w},
                         {"height", h},
                         {"frame", options.frame},
                         {"ground_truth_samples_per_pixel", options.groundTruthSamples * options.groundTruthSamples},
                         {"edge_pixels", std::count(reference.edges.begin(), reference.edges.end(), 1)},
                         {"renderer", info.renderer},
                         {"renderer_summary", info.summary()},
                         {"gl_version", info.version},
                         {"egl_platform", info.platform},
                         {"gl_max_samples", info.maxSamples},
                         {"copy_gb_per_s", copyGigabytesPerSecond},
                         {"shading_floor_evals_per_pixel", shadingFloor},
                         {"shading_floor_samples", options.base.samples},
                         {"metric_space", "display (tonemapped sRGB, 8-bit) values in [0,1]"},
                         {"rows", rows}};
  const std::string table = benchTable(rows) + "\n" + floorTable(rows) + sliceTable(rows, "method", "plugin.");
  std::printf("%s", table.c_str());
  std::printf("renderer: %s\n", info.summary().c_str());
  if (!options.json.empty()) {
    ensureParent(options.json);
    std::ofstream(options.json) << document.dump(2) << "\n";
  }
  if (!options.csv.empty()) writeBenchCsv(options.csv, rows);
  if (!options.report.empty()) writeBenchReport(options, document, table);
  return kExitOk;
}

int runRecord(const RecordOptions& options) {
  if (options.keys < 2) throw std::invalid_argument("--keys must be at least 2");
  const host::Scene scene = host::loadScene(options.scene, false);
  if (options.fit && scene.objects.empty()) throw std::invalid_argument("--fit: the scene has no object to frame");
  const host::Camera camera =
      options.fit ? host::fitCamera(scene.objects, scene.camera, scene.camera.target - scene.camera.position)
                  : scene.camera;
  const glm::vec3 up = glm::normalize(camera.up);
  const glm::vec3 offset = camera.position - camera.target;
  nlohmann::json keys = nlohmann::json::array();
  for (int k = 0; k < options.keys; ++k) {
    const float s = float(k) / float(options.keys - 1);
    const float angle = glm::radians(options.orbitDegrees) * s;
    // Rodrigues' rotation of the offset about the up axis, then the dolly.
    const glm::vec3 rotated = offset * std::cos(angle) + glm::cross(up, offset) * std::sin(angle) +
                              up * glm::dot(up, offset) * (1.0f - std::cos(angle));
    const glm::vec3 position = camera.target + rotated * (1.0f + (options.dolly - 1.0f) * s);
    keys.push_back({{"t", options.seconds * s},
                    {"position", {position.x, position.y, position.z}},
                    {"target", {camera.target.x, camera.target.y, camera.target.z}}});
  }
  const nlohmann::json path = {{"comment", "recorded by retroaa record: " + std::to_string(options.orbitDegrees) +
                                               " degree orbit, dolly " + std::to_string(options.dolly)},
                               {"fps", options.framesPerSecond},
                               {"keys", keys}};
  ensureParent(options.out);
  std::ofstream(options.out) << path.dump(1) << "\n";
  std::printf("wrote %s: %d frames\n", options.out.c_str(),
              int(std::floor(options.seconds * options.framesPerSecond)) + 1);
  return kExitOk;
}

namespace {
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// What malloc has handed out and not had back: beside the resident figure, it tells live allocations
// (ours, or the driver's through malloc) from freed memory the heap keeps and the driver's own mappings.
double heapInUseMiB() { return double(mallinfo2().uordblks) / (1024.0 * 1024.0); }
// Freed memory malloc keeps in its arenas for reuse (resident where it was touched).
double heapFreeHeldMiB() { return double(mallinfo2().fordblks) / (1024.0 * 1024.0); }

// Resident memory by kind of mapping (/proc/self/smaps): the main heap (brk), anonymous mappings (malloc's
// large blocks and its threads' arenas, llvmpipe's compiled shader code and buffers) and files.
struct ResidentSplit {
  double heapMiB = 0, anonymousMiB = 0, filesMiB = 0;
};
ResidentSplit residentSplit() {
  ResidentSplit split;
  std::ifstream smaps("/proc/self/smaps");
  double* current = nullptr;
  for (std::string line; std::getline(smaps, line);) {
    if (line.empty()) continue;
    if (std::isxdigit(static_cast<unsigned char>(line[0])) && line.find('-') < line.find(' ')) {
      // "start-end perms offset dev inode [path]": the path is the sixth field.
      std::istringstream fields(line);
      std::string range, perms, offset, device, inode, path;
      fields >> range >> perms >> offset >> device >> inode >> path;
      current = path == "[heap]"                 ? &split.heapMiB
                : path.empty() || path[0] == '[' ? &split.anonymousMiB
                                                 : &split.filesMiB;
    } else if (current && line.rfind("Rss:", 0) == 0) {
      *current += std::atof(line.c_str() + 4) / 1024.0;
    }
  }
  return split;
}
}  // namespace

int runSoak(const SoakOptions& options) {
  host::HeadlessContext context;
  Session session("default", options.width, options.height, context.info().summary());
  const std::vector<std::string> methods = expandMethodList("all");
  const int sizes[3][2] = {{options.width, options.height},
                           {options.width + 17, options.height + 9},
                           {options.width / 2 + 3, options.height / 2 + 5}};
  const int samples[] = {1, 2, 4, 8};
  session.configure(retroaa::Config{});
  session.renderer->renderFrame(session.camera(0));
  const int objectsAtStart = session.plugin().stats().glObjectsHeld;
  const int errorsAtStart = context.debugErrorCount();
  double residentAfterWarmUp = 0, residentPeak = 0;
  for (int frame = 0; frame < options.frames; ++frame) {
    retroaa::Config config = parseMethodSpec(methods[frame % methods.size()], {}).config;
    config.samples = samples[(frame / 3) % 4];
    config.edgeDetector = retroaa::EdgeDetector(frame % 5);
    config.aggregateCount = 1 + frame % 4;
    config.fxaa = frame % 7 == 0;
    config.reconstructCompute = frame % 2 == 0;
    config.resolveCompute = frame % 3 == 1;
    session.configure(config);
    if (frame % 50 == 49) {
      const int* size = sizes[(frame / 50) % 3];
      session.renderer->resize(size[0], size[1]);
    }
    session.renderer->renderFrame(session.camera(frame % std::max(session.scene.path.frameCount(), 1)));
    if (frame == std::min(options.frames - 1, 100)) residentAfterWarmUp = residentMiB();
    residentPeak = std::max(residentPeak, residentMiB());
    // The settings above repeat every 4200 frames (their periods' least common multiple, with the sizes'): a
    // cache that fills while new combinations come (the driver's shader variants) flattens after one period,
    // a leak does not.
    if ((frame + 1) % 1050 == 0) {
      const ResidentSplit split = residentSplit();
      std::printf(
          "soak: frame %d, resident %.1f MiB (heap %.1f, anonymous %.1f, files %.1f), heap in use %.2f MiB, "
          "free in malloc's arenas %.2f MiB\n",
          frame + 1, residentMiB(), split.heapMiB, split.anonymousMiB, split.filesMiB, heapInUseMiB(),
          heapFreeHeldMiB());
    }
  }
  session.renderer->resize(options.width, options.height);
  session.configure(retroaa::Config{});
  session.renderer->renderFrame(session.camera(0));
  const int objectsAtEnd = session.plugin().stats().glObjectsHeld;
  const int glErrors = context.debugErrorCount() - errorsAtStart;
  const double growth = residentPeak - residentAfterWarmUp;
  std::printf("soak: %d frames, %zu methods x 4 sample counts x 5 detectors, 3 sizes\n", options.frames,
              methods.size());
  std::printf(
      "soak: plugin GL objects %d at start, %d at end; GL errors %d; resident memory %.1f MiB after warm-up, peak %.1f "
      "MiB (growth %.1f, bound %.0f)\n",
      objectsAtStart, objectsAtEnd, glErrors, residentAfterWarmUp, residentPeak, growth, options.maxGrowthMiB);
  const bool ok =
      objectsAtEnd == objectsAtStart && glErrors == 0 && growth <= options.maxGrowthMiB && session.lastError().empty();
  if (!session.lastError().empty()) std::printf("soak: plugin error: %s\n", session.lastError().c_str());
  std::printf("soak: %s\n", ok ? "passed" : "FAILED");
  return ok ? kExitOk : kExitCheckFailed;
}

std::string configReference(bool markdown) {
  std::ostringstream out;
  if (markdown) out << "| key | default | allowed | read by | effect |\n|---|---|---|---|---|\n";
  for (const retroaa::ConfigKey& key : retroaa::configKeys()) {
    const std::string defaultValue = *key.defaultValue ? key.defaultValue : "(empty)";
    std::string readers;
    for (const char* method : key.methods) readers += (readers.empty() ? "" : ", ") + std::string(method);
    if (markdown)
      out << "| `" << key.name << "` | `" << defaultValue << "` | " << key.allowed << " | "
          << (readers.empty() ? "every method" : readers) << " | " << key.effect << " |\n";
    else
      out << key.name << " = " << defaultValue << "  [" << key.allowed << "]  "
          << (readers.empty() ? "" : "(" + readers + ") ") << key.effect << "\n";
  }
  return out.str();
}

}  // namespace app
