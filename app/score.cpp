#include "score.h"

#include "commands.h"
#include "image_io.h"
#include "metrics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

void writeCrop(const DisplayImage& image, int x0, int y0, int size, int zoom, const std::string& path) {
  std::vector<uint8_t> rgba(size_t(size * zoom) * size * zoom * 4, 255);
  for (int y = 0; y < size * zoom; ++y)
    for (int x = 0; x < size * zoom; ++x) {
      const int sx = std::min(image.width - 1, x0 + x / zoom), sy = std::min(image.height - 1, y0 + y / zoom);
      for (int c = 0; c < 3; ++c)
        rgba[(size_t(y) * size * zoom + x) * 4 + c] =
            uint8_t(std::lround(std::clamp(image.rgb[(size_t(sy) * image.width + sx) * 3 + c], 0.0f, 1.0f) * 255));
    }
  writeImage8(path, size * zoom, size * zoom, rgba);
}

// One captured method, scored against the reference.
struct ScoredCapture {
  nlohmann::json capture;
  DisplayImage image;
  ErrorMetrics metrics;
};

// Every record of the engine's capture.jsonl that has an image, scored; a record without one is named.
std::vector<ScoredCapture> readCaptures(const ScoreOptions& options, const DisplayImage& reference,
                                        const std::vector<uint8_t>& edges) {
  const std::string captureLog = options.captureDir + "/capture.jsonl";
  std::ifstream in(captureLog);
  if (!in) throw std::invalid_argument(captureLog + ": cannot read (run the engine's capture first)");
  std::vector<ScoredCapture> rows;
  int lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    if (line.empty()) continue;
    nlohmann::json capture = nlohmann::json::parse(line, nullptr, false);
    if (capture.is_discarded() || !capture.is_object() || !capture.contains("spec"))
      throw std::invalid_argument(captureLog + ":" + std::to_string(lineNumber) + ": not a capture record");
    if (!capture.contains("image")) {
      std::fprintf(stderr, "retroaa score: %s was not captured: %s\n", capture.value("spec", "?").c_str(),
                   capture.value("error", "no image").c_str());
      continue;
    }
    DisplayImage image = readDisplay(options.captureDir + "/" + capture["image"].get<std::string>());
    if (image.width != reference.width || image.height != reference.height)
      throw std::invalid_argument(capture["image"].get<std::string>() + " is " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height) + "; the reference filtered by " +
                                  std::to_string(options.factor) + " is " + std::to_string(reference.width) + "x" +
                                  std::to_string(reference.height));
    const ErrorMetrics metrics = compare(image, reference, edges);
    rows.push_back({std::move(capture), std::move(image), metrics});
  }
  if (rows.empty()) throw std::invalid_argument(captureLog + ": no captured method");
  return rows;
}

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

void writeReferenceImages(const ScoreOptions& options, const DisplayImage& reference, const std::string& out) {
  writeCrop(reference, options.cropX, options.cropY, options.cropSize, 4, out + "/crop-reference.png");
  std::vector<uint8_t> rgba(reference.rgb.size() / 3 * 4, 255);
  for (size_t p = 0; p < reference.rgb.size() / 3; ++p)
    for (int c = 0; c < 3; ++c)
      rgba[p * 4 + c] = uint8_t(std::lround(std::clamp(reference.rgb[p * 3 + c], 0.f, 1.f) * 255));
  writeImage8(out + "/reference.png", reference.width, reference.height, rgba);
}

}  // namespace

int score(const ScoreOptions& options) {
  if (options.factor < 1 || options.factor > 16) throw std::invalid_argument("--factor must be 1..16");
  const DisplayImage big = readDisplay(options.reference);
  std::vector<float> spread;
  const DisplayImage reference = downsample(big, options.factor, spread);
  const std::vector<uint8_t> edges = edgeMaskFromSpread(spread);
  const std::string out = options.out.empty() ? options.captureDir : options.out;
  const std::vector<ScoredCapture> rows = readCaptures(options, reference, edges);

  // `off` (the engine's stock path) is the baseline of the ratios and of the sky check: sky must stay
  // as off has it.
  const ScoredCapture* off = nullptr;
  for (const ScoredCapture& row : rows)
    if (row.capture["spec"] == "off") off = &row;
  const double offWall = off ? off->capture.value("wall_ms", 0.0) : 0.0;
  const std::vector<size_t> sky = off ? skyPixels(options, big, reference) : std::vector<size_t>{};

  nlohmann::json report = nlohmann::json::array();
  std::ostringstream md;
  md << "| method | PSNR dB | edge PSNR dB | interior PSNR dB | evals/px | wall ms | × off | retroaa passes GPU ms | "
        "plugin MB | sky kept |\n|---|---|---|---|---|---|---|---|---|---|\n";
  char buffer[512];
  for (const ScoredCapture& row : rows) {
    const nlohmann::json& r = row.capture.contains("retroaa") ? row.capture["retroaa"] : nlohmann::json::object();
    double passMs = 0;
    if (r.contains("passes"))
      for (const auto& pass : r["passes"].items()) passMs += pass.value().get<double>();
    const nlohmann::json kept = off ? skyKept(row.image, off->image, sky) : nlohmann::json();
    const double wall = row.capture.value("wall_ms", 0.0);
    nlohmann::json entry = {{"spec", row.capture["spec"]},
                            {"psnr_db", row.metrics.psnrDb},
                            {"edge_psnr_db", row.metrics.edgePsnrDb},
                            {"interior_psnr_db", row.metrics.interiorPsnrDb},
                            {"ssim", row.metrics.ssim},
                            {"edge_pixels", row.metrics.edgePixels},
                            {"evaluations_per_pixel", r.value("evaluations_per_pixel", 1.0)},
                            {"wall_ms", wall},
                            {"wall_vs_off", offWall > 0 ? wall / offWall : 0.0},
                            {"passes_ms", r.value("passes", nlohmann::json::object())},
                            {"plugin_bytes", r.value("plugin_bytes", 0)},
                            {"warnings", r.value("warnings", 0)},
                            {"sky_pixels", sky.size()},
                            {"sky_kept", kept}};
    report.push_back(entry);
    std::snprintf(buffer, sizeof buffer, "| `%s` | %.2f | %.2f | %.2f | %.2f | %.0f | %.2f | %.1f | %.1f | %s |\n",
                  row.capture["spec"].get<std::string>().c_str(), row.metrics.psnrDb, row.metrics.edgePsnrDb,
                  row.metrics.interiorPsnrDb, entry["evaluations_per_pixel"].get<double>(), wall,
                  offWall > 0 ? wall / offWall : 0.0, passMs, entry["plugin_bytes"].get<double>() / 1048576.0,
                  kept.is_null() ? "–" : std::to_string(kept.get<double>()).substr(0, 6).c_str());
    md << buffer;
    if (options.cropSize > 0)
      writeCrop(row.image, options.cropX, options.cropY, options.cropSize, 4,
                out + "/crop-" + row.capture["image"].get<std::string>());
  }
  if (options.cropSize > 0) writeReferenceImages(options, reference, out);
  md << "\nReference: " << options.reference << " box-filtered " << options.factor << "×" << options.factor
     << " in linear light; " << std::count(edges.begin(), edges.end(), 1) << " edge pixels (luma spread > 0.03); "
     << sky.size()
     << " sky pixels (no geometry within a pixel of them in the reference), kept = within 1/255 of off.\n";
  std::ofstream(out + "/report.md") << md.str();
  std::ofstream(out + "/report.json") << report.dump(2) << "\n";
  std::printf("%s", md.str().c_str());
  return kExitOk;
}

}  // namespace app
