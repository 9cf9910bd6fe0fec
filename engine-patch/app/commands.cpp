#include "commands.h"

#include "ground_truth.h"
#include "headless_context.h"
#include "image_io.h"
#include "metrics.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"
#include "session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unistd.h>
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

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

Session::Session(const host::HeadlessContext& context, const std::string& scenePath, int width, int height)
    : context(context), scene(host::loadScene(scenePath)) {
  renderer = std::make_unique<host::Renderer>(scene, width, height);
  auto created = patch::RetroaaHooks::create(renderer->targets(), retroaa::Config{});
  if (!created) throw std::runtime_error("retroaa: " + created.error().message);
  hooks = std::move(created.value());
  renderer->setHooks(hooks.get());
}

void Session::configure(const retroaa::Config& config) {
  const retroaa::Status status = hooks->plugin().reconfigure(config);
  if (!status) throw std::invalid_argument(status.error().message);
}

std::map<std::string, std::string> Session::metadata(const std::string& method) const {
  return {{"retroaa:method", method},
          {"retroaa:scene", scene.name},
          {"retroaa:renderer", context.info().summary()},
          {"retroaa:config", retroaa::toConfigText(hooks->plugin().config())}};
}

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
  std::string rest = spec;
  // Settings after '@' apply to this row only: adaptive@adaptive_shading_scale=4@adaptive_depth_scale=1
  for (size_t at = rest.rfind('@'); at != std::string::npos; at = rest.rfind('@')) {
    const std::string setting = rest.substr(at + 1);
    const size_t equals = setting.find('=');
    if (equals == std::string::npos)
      throw std::invalid_argument("method '" + spec + "': expected key=value after '@', got '" + setting + "'");
    const retroaa::Status status = retroaa::applySetting(out.config, setting.substr(0, equals), setting.substr(equals + 1));
    if (!status) throw std::invalid_argument("method '" + spec + "': " + status.error().message);
    rest = rest.substr(0, at);
  }
  // Stacked post filters: +coverage, +fxaa, in either order.
  for (size_t plus = rest.rfind('+'); plus != std::string::npos; plus = rest.rfind('+')) {
    const std::string stacked = rest.substr(plus + 1);
    if (stacked == "fxaa")
      out.config.fxaa = true;
    else if (stacked == "coverage")
      out.config.coverageFilter = true;
    else
      throw std::invalid_argument("method '" + spec + "': only '+fxaa' and '+coverage' can be stacked");
    rest = rest.substr(0, plus);
  }
  const size_t slash = rest.find('/');
  if (slash != std::string::npos) {
    const retroaa::Status status = retroaa::applySetting(out.config, "resolve_weighting", rest.substr(slash + 1));
    if (!status) throw std::invalid_argument("method '" + spec + "': " + status.error().message);
    rest = rest.substr(0, slash);
  }
  const retroaa::Status status = retroaa::applySetting(out.config, "method", rest);
  if (!status) throw std::invalid_argument("method '" + spec + "': " + status.error().message);
  return out;
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
      for (const retroaa::MethodInfo& row : retroaa::methodTable())
        add(item == "all" ? row.sweepSpecs : item == "each" ? row.regressSpec : row.tuneSpecs);
    else
      add(item);
  }
  return out;
}

int runRender(const RenderOptions& options) {
  host::HeadlessContext context;
  Session session(context, options.scene, options.width, options.height);
  const host::Camera camera = session.camera(options.frame);
  const std::string ext = lowerExtension(options.out);
  if (ext != ".png" && ext != ".exr") throw std::invalid_argument("--out must end in .png or .exr, got '" + options.out + "'");
  ensureParent(options.out);

  std::vector<uint8_t> display;
  std::vector<float> radiance;
  if (options.method == "ground-truth") {
    const host::GroundTruth truth = host::renderGroundTruth(*session.renderer, camera, options.groundTruthSamples);
    display = truth.display;
    radiance = truth.radiance;
  } else {
    session.configure(options.method.empty() ? options.base : parseMethodSpec(options.method, options.base).config);
    session.renderer->renderFrame(camera);
    display = session.renderer->readDisplay();
    radiance = session.renderer->readLight();
  }
  const std::string methodName = options.method.empty() ? retroaa::toString(session.hooks->plugin().config().method) : options.method;
  auto meta = session.metadata(methodName);
  if (!options.show.empty()) {
    if (options.show != "edges" && options.show != "samples" && options.show != "aggregates")
      throw std::invalid_argument("--show must be edges, samples or aggregates, got '" + options.show + "'");
    const retroaa::Stats stats = session.hooks->plugin().stats();
    display = visualiseCounts(options.show, session.hooks->plugin().readSliceCounts(), display, options.width,
                              options.height, std::max(stats.samples, 1));
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
  std::printf("wrote %s (%s)\n", options.out.c_str(), session.context.info().summary().c_str());
  return kExitOk;
}

int runBench(const BenchOptions& options) {
  std::vector<MethodSpec> specs;
  for (const std::string& name : expandMethodList(options.methods)) specs.push_back(parseMethodSpec(name, options.base));
  if (specs.empty()) throw std::invalid_argument("--methods names no method");

  host::HeadlessContext context;
  Session session(context, options.scene, options.width, options.height);
  const host::Camera camera = session.camera(options.frame);
  const int w = options.width, h = options.height;
  std::fprintf(stderr, "bench: %s, %dx%d, %zu triangles, %zu lights; ground truth %dx%d per pixel...\n",
               session.scene.name.c_str(), w, h, session.scene.triangleCount(), session.scene.lights.size(),
               options.groundTruthSamples, options.groundTruthSamples);
  const host::GroundTruth truth = host::renderGroundTruth(*session.renderer, camera, options.groundTruthSamples);
  const DisplayImage reference = DisplayImage::fromRgba8(w, h, truth.display);
  const std::vector<uint8_t> edges = edgeMaskFromSpread(truth.lumaStdDev);
  if (!options.imagesDirectory.empty()) {
    std::filesystem::create_directories(options.imagesDirectory);
    writeImage8(options.imagesDirectory + "/ground-truth.png", w, h, truth.display, session.metadata("ground-truth"));
    std::vector<uint8_t> mask(size_t(w) * h * 4, 255);
    for (size_t p = 0; p < edges.size(); ++p) mask[p * 4] = mask[p * 4 + 1] = mask[p * 4 + 2] = edges[p] ? 255 : 0;
    writeImage8(options.imagesDirectory + "/edge-mask.png", w, h, mask);
  }

  // The per-sample reference at the run's sample count: every row's error against it.
  retroaa::Config referenceConfig = options.base;
  referenceConfig.method = retroaa::Method::PerSample;
  referenceConfig.fxaa = false;
  session.configure(referenceConfig);
  session.renderer->renderFrame(camera);
  const DisplayImage perSampleReference = DisplayImage::fromRgba8(w, h, session.renderer->readDisplay());

  nlohmann::json rows = nlohmann::json::array();
  double offFrameMs = 0, perSampleFrameMs = 0;
  for (const MethodSpec& spec : specs) {
    std::fprintf(stderr, "bench: %s\n", spec.name.c_str());
    retroaa::Config config = spec.config;
    config.measureGpuTime = true;
    session.configure(config);
    session.renderer->measureTime = true;
    session.renderer->renderFrame(camera);  // warm-up: shader compilation, first-touch allocation
    std::vector<double> frameMs, modelMs, lightingMs, tonemapMs;
    std::map<std::string, std::vector<double>> pluginMs;
    for (int r = 0; r < std::max(1, options.repeats); ++r) {
      session.renderer->renderFrame(camera);
      const host::HostTimings& t = session.renderer->timings();
      frameMs.push_back(t.frameMs);
      modelMs.push_back(t.modelPassMs);
      lightingMs.push_back(t.lightingMs);
      tonemapMs.push_back(t.tonemapMs);
      std::map<std::string, double> frameTotals;  // a pass runs once per slice: sum them per frame
      for (const retroaa::PassTime& pass : session.hooks->plugin().stats().passes) frameTotals[pass.name] += pass.ms;
      for (const auto& [name, ms] : frameTotals) pluginMs[name].push_back(ms);
    }
    session.renderer->measureTime = false;
    const retroaa::Stats stats = session.hooks->plugin().stats();
    const std::vector<uint8_t> display = session.renderer->readDisplay();
    const DisplayImage image = DisplayImage::fromRgba8(w, h, display);
    const ErrorMetrics m = compare(image, reference, edges);
    if (spec.name == "off") offFrameMs = median(frameMs);
    if (spec.name == "per-sample") perSampleFrameMs = median(frameMs);

    nlohmann::json passes = {{"model_pass", median(modelMs)}, {"lighting", median(lightingMs)}, {"tonemap_post", median(tonemapMs)}};
    for (const auto& [name, values] : pluginMs) passes["plugin." + name] = median(values);
    nlohmann::json row = {
        {"method", spec.name},
        {"samples", stats.samples},
        {"evals_per_pixel", stats.evaluationsPerPixel()},
        {"lighting_evaluations", stats.lightingEvaluations},
        {"gpu_ms", median(frameMs)},
        {"passes_ms", passes},
        {"plugin_bytes", stats.bytesHeld},
        {"plugin_bytes_per_pixel", double(stats.bytesHeld) / (double(w) * h)},
        {"psnr_db", m.psnrDb},
        {"edge_psnr_db", m.edgePsnrDb},
        {"ssim", m.ssim},
        {"max_abs_error", m.maxAbsError},
        {"psnr_vs_per_sample_db", compare(image, perSampleReference, {}).psnrDb},
        {"slices", stats.slices},
        {"budget_scale", stats.budgetScale},
    };
    rows.push_back(row);
    if (!options.imagesDirectory.empty()) {
      std::string file = spec.name;
      std::replace(file.begin(), file.end(), '/', '-');
      writeImage8(options.imagesDirectory + "/" + file + ".png", w, h, display, session.metadata(spec.name));
      writeImage8(options.imagesDirectory + "/" + file + "-error.png", w, h, errorHeatmap(image, reference));
    }
  }
  // Ratios of times measured in this one run (null where the baseline method was not run).
  for (auto& row : rows) {
    const double ms = row["gpu_ms"].get<double>();
    row["time_vs_off"] = offFrameMs > 0 ? nlohmann::json(ms / offFrameMs) : nlohmann::json(nullptr);
    row["time_vs_per_sample"] = perSampleFrameMs > 0 ? nlohmann::json(ms / perSampleFrameMs) : nlohmann::json(nullptr);
  }

  nlohmann::json document = {
      {"scene", session.scene.name},
      {"width", w},
      {"height", h},
      {"frame", options.frame},
      {"ground_truth_samples_per_pixel", options.groundTruthSamples * options.groundTruthSamples},
      {"edge_pixels", std::count(edges.begin(), edges.end(), 1)},
      {"renderer", session.context.info().renderer},
      {"gl_version", session.context.info().version},
      {"egl_platform", session.context.info().platform},
      {"gl_max_samples", session.context.info().maxSamples},
      {"metric_space", "display (tonemapped sRGB, 8-bit) values in [0,1]"},
      {"rows", rows},
  };

  // A table for the terminal, and for the Markdown report.
  std::ostringstream table;
  table << "| method | samples | evals/px | GPU ms | time vs off | time vs per-sample | plugin B/px | PSNR dB | edge PSNR dB | "
           "SSIM | max err | PSNR vs per-sample |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  auto ratio = [](const nlohmann::json& value) {
    if (value.is_null()) return std::string("-");
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << value.get<double>();
    return s.str();
  };
  for (const auto& row : rows) {
    table << std::fixed << "| " << row["method"].get<std::string>() << " | " << row["samples"].get<int>() << " | "
          << std::setprecision(3) << row["evals_per_pixel"].get<double>() << " | " << std::setprecision(2)
          << row["gpu_ms"].get<double>() << " | "
          << ratio(row["time_vs_off"]) << " | " << ratio(row["time_vs_per_sample"]) << " | " << std::setprecision(1)
          << row["plugin_bytes_per_pixel"].get<double>() << " | " << std::setprecision(2) << row["psnr_db"].get<double>()
          << " | " << row["edge_psnr_db"].get<double>() << " | " << std::setprecision(4) << row["ssim"].get<double>()
          << " | " << std::setprecision(3) << row["max_abs_error"].get<double>() << " | " << std::setprecision(2)
          << row["psnr_vs_per_sample_db"].get<double>() << " |\n";
  }
  std::printf("%s", table.str().c_str());
  std::printf("renderer: %s\n", session.context.info().summary().c_str());

  if (!options.json.empty()) {
    ensureParent(options.json);
    std::ofstream(options.json) << document.dump(2) << "\n";
  }
  if (!options.csv.empty()) {
    ensureParent(options.csv);
    std::ofstream csv(options.csv);
    const char* columns[] = {"method", "samples", "evals_per_pixel", "gpu_ms", "time_vs_off", "time_vs_per_sample",
                             "plugin_bytes_per_pixel", "psnr_db", "edge_psnr_db", "ssim", "max_abs_error",
                             "psnr_vs_per_sample_db"};
    for (const char* column : columns) csv << column << (column == columns[11] ? "\n" : ",");
    for (const auto& row : rows)
      for (const char* column : columns)
        csv << (row[column].is_string() ? row[column].get<std::string>() : row[column].dump())
            << (column == columns[11] ? "\n" : ",");
  }
  if (!options.report.empty()) {
    ensureParent(options.report);
    std::ofstream md(options.report);
    md << "# retroaa speed vs error: " << session.scene.name << "\n\n"
       << "Renderer: " << session.context.info().summary() << "  \n"
       << "Size " << w << "x" << h << ", ground truth " << options.groundTruthSamples << "x" << options.groundTruthSamples
       << " supersamples per pixel lit per sample (box filter on linear radiance), " << document["edge_pixels"]
       << " edge pixels. Errors on tonemapped display values in [0,1]; times are the median of " << options.repeats
       << " frames (GPU timer queries).\n\n"
       << table.str() << "\n";
    if (!options.imagesDirectory.empty()) {
      const auto relative = std::filesystem::relative(options.imagesDirectory, std::filesystem::path(options.report).parent_path()).string();
      md << "Ground truth: ![](" << relative << "/ground-truth.png) edge mask: ![](" << relative << "/edge-mask.png)\n\n";
      for (const auto& row : rows) {
        std::string file = row["method"].get<std::string>();
        std::replace(file.begin(), file.end(), '/', '-');
        md << "`" << row["method"].get<std::string>() << "`: ![](" << relative << "/" << file << ".png) error: ![]("
           << relative << "/" << file << "-error.png)\n\n";
      }
    }
  }
  return kExitOk;
}

int runRecord(const RecordOptions& options) {
  if (options.keys < 2) throw std::invalid_argument("--keys must be at least 2");
  const host::Scene scene = host::loadScene(options.scene, false);
  const host::Camera& camera = scene.camera;
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
  const nlohmann::json path = {
      {"comment", "recorded by retroaa record: " + std::to_string(options.orbitDegrees) + " degree orbit, dolly " +
                      std::to_string(options.dolly)},
      {"fps", options.framesPerSecond},
      {"keys", keys}};
  ensureParent(options.out);
  std::ofstream(options.out) << path.dump(1) << "\n";
  std::printf("wrote %s: %d frames\n", options.out.c_str(), int(std::floor(options.seconds * options.framesPerSecond)) + 1);
  return kExitOk;
}

namespace {
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}
}  // namespace

int runSoak(const SoakOptions& options) {
  host::HeadlessContext context;
  Session session(context, "default", options.width, options.height);
  const std::vector<std::string> methods = expandMethodList("all");
  const int sizes[3][2] = {{options.width, options.height}, {options.width + 17, options.height + 9}, {options.width / 2 + 3, options.height / 2 + 5}};
  const int samples[] = {1, 2, 4, 8};
  session.configure(retroaa::Config{});
  session.renderer->renderFrame(session.camera(0));
  const int objectsAtStart = session.hooks->plugin().stats().glObjectsHeld;
  const int errorsAtStart = context.debugErrorCount();
  double residentAfterWarmUp = 0, residentPeak = 0;
  for (int frame = 0; frame < options.frames; ++frame) {
    retroaa::Config config = parseMethodSpec(methods[frame % methods.size()], {}).config;
    config.samples = samples[(frame / 3) % 4];
    config.edgeDetector = retroaa::EdgeDetector(frame % 5);
    config.aggregateCount = 1 + frame % 4;
    config.fxaa = frame % 7 == 0;
    session.configure(config);
    if (frame % 50 == 49) {
      const int* size = sizes[(frame / 50) % 3];
      session.renderer->resize(size[0], size[1]);
    }
    session.renderer->renderFrame(session.camera(frame % std::max(session.scene.path.frameCount(), 1)));
    if (frame == std::min(options.frames - 1, 100)) residentAfterWarmUp = residentMiB();
    residentPeak = std::max(residentPeak, residentMiB());
  }
  session.renderer->resize(options.width, options.height);
  session.configure(retroaa::Config{});
  session.renderer->renderFrame(session.camera(0));
  const int objectsAtEnd = session.hooks->plugin().stats().glObjectsHeld;
  const int glErrors = context.debugErrorCount() - errorsAtStart;
  const double growth = residentPeak - residentAfterWarmUp;
  std::printf("soak: %d frames, %zu methods x 4 sample counts x 5 detectors, 3 sizes\n", options.frames, methods.size());
  std::printf("soak: plugin GL objects %d at start, %d at end; GL errors %d; resident memory %.1f MiB after warm-up, peak %.1f MiB (growth %.1f, bound %.0f)\n",
              objectsAtStart, objectsAtEnd, glErrors, residentAfterWarmUp, residentPeak, growth, options.maxGrowthMiB);
  const bool ok = objectsAtEnd == objectsAtStart && glErrors == 0 && growth <= options.maxGrowthMiB &&
                  session.hooks->lastError().empty();
  if (!session.hooks->lastError().empty()) std::printf("soak: plugin error: %s\n", session.hooks->lastError().c_str());
  std::printf("soak: %s\n", ok ? "passed" : "FAILED");
  return ok ? kExitOk : kExitCheckFailed;
}

std::string configReference(bool markdown) {
  std::ostringstream out;
  if (markdown) out << "| key | default | allowed | effect |\n|---|---|---|---|\n";
  for (const retroaa::ConfigKey& key : retroaa::configKeys()) {
    const std::string defaultValue = *key.defaultValue ? key.defaultValue : "(empty)";
    if (markdown)
      out << "| `" << key.name << "` | `" << defaultValue << "` | " << key.allowed << " | " << key.effect << " |\n";
    else
      out << key.name << " = " << defaultValue << "  [" << key.allowed << "]  " << key.effect << "\n";
  }
  return out.str();
}

}  // namespace app
