#include "score.h"

#include "bounded_json.h"
#include "commands.h"
#include "image_io.h"
#include "metrics.h"
#include "scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace app {

namespace {

float toLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }
float toDisplay(float v) { return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f; }

DisplayImage readDisplay(const std::string& path) {
  DisplayImage image;
  image.rgb = readImageRgb(path, image.width, image.height);
  return image;
}

// The reference box-filtered in linear light to the capture's size, and the spread of each block's
// display luma (its edge mask, as the in-repo ground truth's).
DisplayImage downsample(const DisplayImage& big, int factor, std::vector<float>& lumaSpread) {
  DisplayImage small;
  small.width = big.width / factor;
  small.height = big.height / factor;
  small.rgb.assign(size_t(small.width) * small.height * 3, 0.0f);
  lumaSpread.assign(size_t(small.width) * small.height, 0.0f);
  const float n = float(factor * factor);
  for (int y = 0; y < small.height; ++y)
    for (int x = 0; x < small.width; ++x) {
      double sum[3] = {0, 0, 0}, luma = 0, lumaSquared = 0;
      for (int j = 0; j < factor; ++j)
        for (int i = 0; i < factor; ++i) {
          const int bx = x * factor + i, by = y * factor + j;
          const float* p = &big.rgb[(size_t(by) * big.width + bx) * 3];
          for (int c = 0; c < 3; ++c) sum[c] += toLinear(p[c]);
          const double l = big.luma(bx, by);
          luma += l;
          lumaSquared += l * l;
        }
      for (int c = 0; c < 3; ++c) small.rgb[(size_t(y) * small.width + x) * 3 + c] = toDisplay(float(sum[c] / n));
      const double mean = luma / n;
      lumaSpread[size_t(y) * small.width + x] = float(std::sqrt(std::max(0.0, lumaSquared / n - mean * mean)));
    }
  return small;
}

// A crop enlarged 4× (nearest), so single pixels show.
void writeCrop(const DisplayImage& image, const Crop& crop, const std::string& path) {
  const int zoom = 4, size = crop.size;
  std::vector<uint8_t> rgba(size_t(size * zoom) * size * zoom * 4, 255);
  for (int y = 0; y < size * zoom; ++y)
    for (int x = 0; x < size * zoom; ++x) {
      const int sx = std::min(image.width - 1, crop.x + x / zoom), sy = std::min(image.height - 1, crop.y + y / zoom);
      for (int c = 0; c < 3; ++c)
        rgba[(size_t(y) * size * zoom + x) * 4 + c] =
            uint8_t(std::lround(std::clamp(image.rgb[(size_t(sy) * image.width + sx) * 3 + c], 0.0f, 1.0f) * 255));
    }
  writeImage8(path, size * zoom, size * zoom, rgba);
}

// A reference frame: the supersampled render box-filtered to the capture's size, and its edge mask.
struct ReferenceFrame {
  DisplayImage big, image;
  std::vector<uint8_t> edges;
};

ReferenceFrame readReference(const std::string& path, int factor) {
  ReferenceFrame frame;
  frame.big = readDisplay(path);
  std::vector<float> spread;
  frame.image = downsample(frame.big, factor, spread);
  frame.edges = edgeMaskFromSpread(spread);
  return frame;
}

// The records of a capture.jsonl that name an image, in order; a record without one is named on stderr.
std::vector<nlohmann::json> readRecords(const std::string& folder) {
  const std::string captureLog = folder + "/capture.jsonl";
  std::string problem;
  const std::optional<std::string> text = host::readUserTextFile(captureLog, problem);
  if (!text)
    throw std::invalid_argument(captureLog + ": cannot read (" + problem + "; run the engine's capture first)");
  std::istringstream in(*text);
  std::vector<nlohmann::json> records;
  int lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    if (line.empty()) continue;
    const std::string where = captureLog + ":" + std::to_string(lineNumber);
    nlohmann::json record;
    try {
      record = host::parseBoundedJson(line, where);
    } catch (const host::SceneError& e) {
      throw std::invalid_argument(std::string(e.what()) + " (not a capture record)");
    }
    if (!record.is_object() || !record.contains("spec") || !record["spec"].is_string() ||
        (record.contains("image") && !record["image"].is_string()) ||
        (record.contains("frame") && !record["frame"].is_number_integer()))
      throw std::invalid_argument(captureLog + ":" + std::to_string(lineNumber) + ": not a capture record");
    if (!record.contains("image")) {
      std::fprintf(stderr, "retroaa score: %s was not captured: %s\n", record["spec"].get<std::string>().c_str(),
                   record.value("error", "no image").c_str());
      continue;
    }
    records.push_back(std::move(record));
  }
  if (records.empty()) throw std::invalid_argument(captureLog + ": no captured method");
  return records;
}

// The references the records are scored against: one image for all, or, with a reference folder, the
// reference capture's image of each record's frame.
class References {
 public:
  References(const ScoreOptions& options) : options_(options) {
    if (!std::filesystem::is_directory(options.reference)) {
      single_ = readReference(options.reference, options.factor);
      return;
    }
    for (const nlohmann::json& record : readRecords(options.reference))
      if (record.contains("frame")) paths_[record["frame"].get<int>()] = record["image"].get<std::string>();
  }
  bool sequence() const { return !single_; }
  // The reference of `record`; a frame the reference folder lacks is an error naming it.
  const ReferenceFrame& of(const nlohmann::json& record) {
    if (single_) return *single_;
    return frame(record.value("frame", -1), record["image"].get<std::string>());
  }
  // Pixels whose reference changed (more than 4/255 in a channel) from the record's frame - 1 to its frame;
  // empty without both. Computed once a frame, whichever method asks.
  const std::vector<uint8_t>& changedAt(const nlohmann::json& record) {
    static const std::vector<uint8_t> none;
    const int at = record.value("frame", -1);
    if (single_ || !paths_.count(at) || !paths_.count(at - 1)) return none;
    auto cached = changed_.find(at);
    if (cached != changed_.end()) return cached->second;
    const std::string image = record["image"].get<std::string>();
    const DisplayImage& a = frame(at - 1, image).image;
    const DisplayImage& b = frame(at, image).image;
    std::vector<uint8_t> changed(a.rgb.size() / 3, 0);
    for (size_t i = 0; i < a.rgb.size(); ++i)
      if (std::abs(a.rgb[i] - b.rgb[i]) > 4.0f / 255) changed[i / 3] = 1;
    return changed_.emplace(at, std::move(changed)).first->second;
  }

 private:
  // The reference capture's frame `at`, read and filtered once; `forImage` names the capture in an error.
  const ReferenceFrame& frame(int at, const std::string& forImage) {
    const auto path = paths_.find(at);
    if (path == paths_.end())
      throw std::invalid_argument(options_.reference + "/capture.jsonl has no frame " + std::to_string(at) + " (for " +
                                  forImage + ")");
    auto cached = frames_.find(at);
    if (cached == frames_.end())
      cached = frames_.emplace(at, readReference(options_.reference + "/" + path->second, options_.factor)).first;
    return cached->second;
  }

  const ScoreOptions& options_;
  std::optional<ReferenceFrame> single_;
  std::map<int, std::string> paths_;
  std::map<int, ReferenceFrame> frames_;
  std::map<int, std::vector<uint8_t>> changed_;  // changedAt's masks, by frame
};

// The figures of one region of an image against its reference (the edge mask cut to it).
ErrorMetrics regionErrors(const DisplayImage& image, const ReferenceFrame& reference, const Region& region) {
  DisplayImage a, b;
  a.width = b.width = region.width, a.height = b.height = region.height;
  std::vector<uint8_t> edges;
  for (int y = region.y; y < region.y + region.height; ++y)
    for (int x = region.x; x < region.x + region.width; ++x) {
      const size_t p = size_t(y) * image.width + x;
      for (int c = 0; c < 3; ++c)
        a.rgb.push_back(image.rgb[p * 3 + c]), b.rgb.push_back(reference.image.rgb[p * 3 + c]);
      edges.push_back(reference.edges[p]);
    }
  return pixelErrors(a, b, edges);
}

// One method over its frames (one frame for a held capture).
struct MethodScore {
  std::string spec, lastImage;
  nlohmann::json lastRecord;
  DisplayImage lastFrame;
  int frames = 0, edgeFrames = 0;
  double psnr = 0, edgePsnr = 0, interiorPsnr = 0, ssim = 0, minPsnr = 1e9, maxPsnr = -1e9, wall = 0;
  double edgePixels = 0;
  std::vector<double> regionPsnr, regionEdgePsnr;
  SequenceError sequence;
};

// The reference's background.png, where its capture wrote one, marks its pixels without geometry: a
// capture pixel whose block and neighbours' blocks are all background there (no wire thinner than a
// pixel, no silhouette reaches it) is sky. Empty without the mask.
std::vector<size_t> skyPixels(const ScoreOptions& options, const DisplayImage& big, const DisplayImage& reference) {
  std::vector<size_t> sky;
  const std::string maskPath = (std::filesystem::path(options.reference).parent_path() / "background.png").string();
  if (!std::filesystem::is_regular_file(maskPath)) return sky;
  const DisplayImage mask = readDisplay(maskPath);
  if (mask.width != big.width || mask.height != big.height)
    throw std::invalid_argument(maskPath + " is not the reference's size");
  const int f = options.factor;
  for (int y = 1; y + 1 < reference.height; ++y)
    for (int x = 1; x + 1 < reference.width; ++x) {
      bool all = true;
      for (int by = (y - 1) * f; all && by < (y + 2) * f; ++by)
        for (int bx = (x - 1) * f; all && bx < (x + 2) * f; ++bx)
          all = mask.rgb[(size_t(by) * mask.width + bx) * 3] > 0.5f;
      if (all) sky.push_back(size_t(y) * reference.width + x);
    }
  return sky;
}

// The reference's edges apart: those of the scene's geometry, and those the sky's own detail makes (an
// edge pixel in `sky`, with no geometry within a pixel: clouds, the sun's rim), as the bench splits its
// stars off (BackgroundEdges::Apart). Both empty without sky pixels.
struct EdgesApart {
  std::vector<uint8_t> model, background;
  size_t modelPixels = 0, backgroundPixels = 0;
};
EdgesApart edgesApart(const std::vector<uint8_t>& edges, const std::vector<size_t>& sky) {
  EdgesApart apart;
  if (sky.empty()) return apart;
  apart.model = edges;
  apart.background.assign(edges.size(), 0);
  for (const size_t p : sky) std::swap(apart.model[p], apart.background[p]);
  apart.modelPixels = size_t(std::count(apart.model.begin(), apart.model.end(), 1));
  apart.backgroundPixels = size_t(std::count(apart.background.begin(), apart.background.end(), 1));
  return apart;
}

// Edge PSNR over `mask`, which marks `pixels` pixels (null where it marks none).
nlohmann::json maskedEdgePsnr(const DisplayImage& image, const DisplayImage& reference,
                              const std::vector<uint8_t>& mask, size_t pixels) {
  if (pixels == 0) return nlohmann::json();
  return compare(image, reference, mask).edgePsnrDb;
}

// The fraction of `sky` within 1/255 of `off` in every channel (null without sky pixels).
nlohmann::json skyKept(const DisplayImage& image, const DisplayImage& off, const std::vector<size_t>& sky) {
  if (sky.empty()) return nlohmann::json();
  int kept = 0;
  for (const size_t p : sky) {
    float worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(image.rgb[p * 3 + c] - off.rgb[p * 3 + c]));
    kept += worst <= 1.0f / 255;
  }
  return double(kept) / double(sky.size());
}

void writeReferenceImage(const DisplayImage& reference, const std::string& path) {
  std::vector<uint8_t> rgba(reference.rgb.size() / 3 * 4, 255);
  for (size_t p = 0; p < reference.rgb.size() / 3; ++p)
    for (int c = 0; c < 3; ++c)
      rgba[p * 4 + c] = uint8_t(std::lround(std::clamp(reference.rgb[p * 3 + c], 0.f, 1.f) * 255));
  writeImage8(path, reference.width, reference.height, rgba);
}

bool isFloor(const std::string& pass) { return pass.size() > 6 && pass.compare(pass.size() - 6, 6, ".floor") == 0; }

// Each captured pass against its floor, for the methods captured with measure_pass_floors=on.
std::string floorTable(const nlohmann::json& report) {
  std::ostringstream md;
  char buffer[512];
  for (const auto& entry : report) {
    const nlohmann::json& passes = entry["passes_ms"];
    for (const auto& [name, ms] : passes.items()) {
      if (isFloor(name) || !passes.contains(name + ".floor")) continue;
      if (md.tellp() == 0)
        md << "\nPasses against their floors (a pass of the same shape that only moves the same bytes, "
              "measure_pass_floors):\n\n| method | pass | ms | floor ms | × floor |\n|---|---|---|---|---|\n";
      const double floor = passes[name + ".floor"].get<double>();
      // A floor the capture could not measure is named with its reason, never a ratio.
      const nlohmann::json unmeasured = entry.value("passes_unmeasured", nlohmann::json::object());
      const std::string why = unmeasured.contains(name + ".floor")
                                  ? "unmeasured: " + unmeasured[name + ".floor"].get<std::string>()
                                  : "unmeasured";
      std::snprintf(buffer, sizeof buffer, "| `%s` | %s | %.2f | %s | %s |\n", entry["spec"].get<std::string>().c_str(),
                    name.c_str(), ms.get<double>(), floor > 0 ? std::to_string(floor).substr(0, 4).c_str() : "–",
                    floor > 0 ? std::to_string(ms.get<double>() / floor).substr(0, 4).c_str() : why.c_str());
      md << buffer;
    }
  }
  return md.str();
}

}  // namespace

Crop parseCrop(const std::string& text) {
  Crop crop;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d%c", &crop.x, &crop.y, &crop.size, &tail) != 3 || crop.x < 0 || crop.y < 0 ||
      crop.size < 1)
    throw std::invalid_argument("--crop expects X,Y,SIZE (pixels, size >= 1), got '" + text.substr(0, 40) + "'");
  return crop;
}

Region parseRegion(const std::string& text) {
  Region region;
  const size_t equals = text.find('=');
  char tail = 0;
  if (equals == std::string::npos || equals == 0 ||
      std::sscanf(text.c_str() + equals + 1, "%d,%d,%d,%d%c", &region.x, &region.y, &region.width, &region.height,
                  &tail) != 4 ||
      region.x < 0 || region.y < 0 || region.width < 1 || region.height < 1)
    throw std::invalid_argument("--region expects NAME=X,Y,W,H (pixels), got '" + text.substr(0, 40) + "'");
  region.name = text.substr(0, equals);
  return region;
}

int score(const ScoreOptions& options) {
  if (options.factor < 1 || options.factor > 16) throw std::invalid_argument("--factor must be 1..16");
  References references(options);
  const std::string out = options.out.empty() ? options.captureDir : options.out;
  std::filesystem::create_directories(out);
  std::vector<MethodScore> methods;  // in the order of their first record
  const ReferenceFrame* lastReference = nullptr;
  for (const nlohmann::json& record : readRecords(options.captureDir)) {
    const std::string spec = record["spec"].get<std::string>();
    auto method = std::find_if(methods.begin(), methods.end(), [&](const MethodScore& m) { return m.spec == spec; });
    if (method == methods.end()) {
      methods.push_back({});
      method = methods.end() - 1;
      method->spec = spec;
    }
    const ReferenceFrame& reference = references.of(record);
    DisplayImage image = readDisplay(options.captureDir + "/" + record["image"].get<std::string>());
    if (image.width != reference.image.width || image.height != reference.image.height)
      throw std::invalid_argument(record["image"].get<std::string>() + " is " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height) + "; the reference filtered by " +
                                  std::to_string(options.factor) + " is " + std::to_string(reference.image.width) +
                                  "x" + std::to_string(reference.image.height));
    for (const Region& region : options.regions)
      if (region.x + region.width > image.width || region.y + region.height > image.height)
        throw std::invalid_argument("--region " + region.name + " reaches past the " + std::to_string(image.width) +
                                    "x" + std::to_string(image.height) + " capture");
    const ErrorMetrics metrics = compare(image, reference.image, reference.edges);
    method->frames++;
    method->psnr += metrics.psnrDb, method->interiorPsnr += metrics.interiorPsnrDb, method->ssim += metrics.ssim;
    if (metrics.edgePixels > 0) method->edgePsnr += metrics.edgePsnrDb, method->edgeFrames++;
    method->edgePixels = metrics.edgePixels;
    method->minPsnr = std::min(method->minPsnr, metrics.psnrDb),
    method->maxPsnr = std::max(method->maxPsnr, metrics.psnrDb);
    method->wall += record.value("wall_ms", 0.0);
    method->regionPsnr.resize(options.regions.size()), method->regionEdgePsnr.resize(options.regions.size());
    for (size_t r = 0; r < options.regions.size(); ++r) {
      const ErrorMetrics inside = regionErrors(image, reference, options.regions[r]);
      method->regionPsnr[r] += inside.psnrDb, method->regionEdgePsnr[r] += inside.edgePsnrDb;
    }
    method->sequence.add(image, reference.image, references.changedAt(record));
    method->lastRecord = record, method->lastImage = record["image"].get<std::string>();
    method->lastFrame = std::move(image);
    lastReference = &reference;
  }

  // `off` (the engine's stock path) is the baseline of the ratios and of the sky check: sky must stay
  // as off has it (a held frame's only: the mask is its reference's).
  const MethodScore* off = nullptr;
  for (const MethodScore& method : methods)
    if (method.spec == "off") off = &method;
  const double offWall = off ? off->wall / off->frames : 0.0;
  const std::vector<size_t> sky = off && !references.sequence()
                                      ? skyPixels(options, lastReference->big, lastReference->image)
                                      : std::vector<size_t>{};
  const EdgesApart apart = edgesApart(lastReference->edges, sky);

  nlohmann::json report = nlohmann::json::array();
  std::ostringstream md;
  const bool sequence = references.sequence();
  md << "| method | " << (sequence ? "frames | " : "") << "PSNR dB | edge PSNR dB | model edge dB | interior PSNR dB | "
     << (sequence ? "PSNR swing dB | flicker | lag PSNR dB | " : "");
  for (const Region& region : options.regions) md << region.name << " PSNR / edge dB | ";
  md << "evals/px | wall ms | × off | retroaa passes GPU ms | own passes ms (× off's wall) | plugin MB | sky kept "
        "|\n|---|";
  const int columns = 11 + (sequence ? 4 : 0) + int(options.regions.size());
  for (int c = 0; c < columns; ++c) md << "---|";
  md << "\n";
  char buffer[256];
  for (const MethodScore& method : methods) {
    const double n = method.frames;
    const nlohmann::json& r =
        method.lastRecord.contains("retroaa") ? method.lastRecord["retroaa"] : nlohmann::json::object();
    // Every plugin pass (the host's lighting inside the slices included: the table's column), and the
    // plugin's own (without the host's lighting); a floor replayed after a pass (measure_pass_floors) is
    // neither: it is compared with its pass below.
    double passMs = 0, ownMs = 0;
    if (r.contains("passes"))
      for (const auto& [name, ms] : r["passes"].items()) {
        if (isFloor(name)) continue;
        passMs += ms.get<double>();
        if (name != "lighting" && name != "slices.lighting") ownMs += ms.get<double>();
      }
    const nlohmann::json kept = off ? skyKept(method.lastFrame, off->lastFrame, sky) : nlohmann::json();
    const double wall = method.wall / n;
    nlohmann::json regions = nlohmann::json::object();
    for (size_t i = 0; i < options.regions.size(); ++i)
      regions[options.regions[i].name] = {{"psnr_db", method.regionPsnr[i] / n},
                                          {"edge_psnr_db", method.regionEdgePsnr[i] / n}};
    const std::optional<double> lag = method.sequence.lagPsnrDb();
    nlohmann::json entry = {
        {"spec", method.spec},
        {"frames", method.frames},
        {"psnr_db", method.psnr / n},
        {"edge_psnr_db", method.edgeFrames ? method.edgePsnr / method.edgeFrames : 0.0},
        {"interior_psnr_db", method.interiorPsnr / n},
        {"ssim", method.ssim / n},
        {"edge_pixels", method.edgePixels},
        {"model_edge_psnr_db", maskedEdgePsnr(method.lastFrame, lastReference->image, apart.model, apart.modelPixels)},
        {"model_edge_pixels", apart.modelPixels},
        {"background_edge_psnr_db",
         maskedEdgePsnr(method.lastFrame, lastReference->image, apart.background, apart.backgroundPixels)},
        {"background_edge_pixels", apart.backgroundPixels},
        {"psnr_swing_db", method.maxPsnr - method.minPsnr},
        {"flicker", method.sequence.flicker()},
        {"lag_psnr_db", lag ? nlohmann::json(*lag) : nlohmann::json()},
        {"regions", regions},
        {"evaluations_per_pixel", r.value("evaluations_per_pixel", 1.0)},
        {"wall_ms", wall},
        {"wall_vs_off", offWall > 0 ? wall / offWall : 0.0},
        {"passes_ms", r.value("passes", nlohmann::json::object())},
        {"passes_unmeasured", r.value("passes_unmeasured", nlohmann::json::object())},
        {"passes_ms_by_run", r.value("passes_by_run", nlohmann::json::object())},
        {"lighting_evaluations_by_slice", r.value("evaluations_by_slice", nlohmann::json::array())},
        {"own_passes_ms", ownMs},
        {"own_passes_vs_off_wall", offWall > 0 ? ownMs / offWall : 0.0},
        {"plugin_bytes", r.value("plugin_bytes", 0)},
        {"warnings", r.value("warnings", 0)},
        {"sky_pixels", sky.size()},
        {"sky_kept", kept}};
    report.push_back(entry);
    md << "| `" << method.spec << "` | ";
    if (sequence) md << method.frames << " | ";
    std::snprintf(buffer, sizeof buffer, "%.2f | %.2f | ", entry["psnr_db"].get<double>(),
                  entry["edge_psnr_db"].get<double>());
    md << buffer;
    if (entry["model_edge_psnr_db"].is_null()) {
      md << "– | ";
    } else {
      std::snprintf(buffer, sizeof buffer, "%.2f | ", entry["model_edge_psnr_db"].get<double>());
      md << buffer;
    }
    std::snprintf(buffer, sizeof buffer, "%.2f | ", entry["interior_psnr_db"].get<double>());
    md << buffer;
    if (sequence) {
      std::snprintf(buffer, sizeof buffer, "%.2f | %.4f | %s | ", entry["psnr_swing_db"].get<double>(),
                    entry["flicker"].get<double>(), lag ? std::to_string(*lag).substr(0, 5).c_str() : "–");
      md << buffer;
    }
    for (size_t i = 0; i < options.regions.size(); ++i) {
      std::snprintf(buffer, sizeof buffer, "%.2f / %.2f | ", method.regionPsnr[i] / n, method.regionEdgePsnr[i] / n);
      md << buffer;
    }
    std::snprintf(buffer, sizeof buffer, "%.2f | %.0f | %.2f | %.1f | %.1f (%.2f) | %.1f | %s |\n",
                  entry["evaluations_per_pixel"].get<double>(), wall, offWall > 0 ? wall / offWall : 0.0, passMs, ownMs,
                  offWall > 0 ? ownMs / offWall : 0.0, entry["plugin_bytes"].get<double>() / 1048576.0,
                  kept.is_null() ? "–" : std::to_string(kept.get<double>()).substr(0, 6).c_str());
    md << buffer;
    for (size_t c = 0; c < options.crops.size(); ++c)
      writeCrop(
          method.lastFrame, options.crops[c],
          out + "/crop" + std::to_string(c + 1) + "-" + std::filesystem::path(method.lastImage).filename().string());
  }
  for (size_t c = 0; c < options.crops.size(); ++c)
    writeCrop(lastReference->image, options.crops[c], out + "/crop" + std::to_string(c + 1) + "-reference.png");
  if (!options.crops.empty()) writeReferenceImage(lastReference->image, out + "/reference.png");
  md << "\nReference: " << options.reference << (sequence ? " (each frame's)" : "") << " box-filtered "
     << options.factor << "×" << options.factor << " in linear light; "
     << std::count(lastReference->edges.begin(), lastReference->edges.end(), 1) << " edge pixels"
     << (sequence ? " in the last frame" : "") << " (luma spread > 0.03)"
     << (sequence ? "; swing: the largest minus the smallest frame's PSNR; flicker: RMS frame-to-frame change of "
                    "the signed error; lag: PSNR where the reference changed since the frame before"
                  : "")
     << "; " << sky.size()
     << " sky pixels (no geometry within a pixel of them in the reference), kept = within 1/255 of off; "
     << "model edges: the " << apart.modelPixels << " edge pixels outside the sky (the other " << apart.backgroundPixels
     << " are the sky's own detail; – without a sky mask, as in a race).\n";
  md << floorTable(report) << sliceTable(report, "spec", "");
  std::ofstream(out + "/report.md") << md.str();
  std::ofstream(out + "/report.json") << report.dump(2) << "\n";
  std::printf("%s", md.str().c_str());
  return kExitOk;
}

}  // namespace app
