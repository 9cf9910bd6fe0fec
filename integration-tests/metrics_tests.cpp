// Metrics on known images, and PSNR cross-checked against OpenImageIO's own comparison (the code
// behind `idiff` and `oiiotool --diff`).
#include "image_io.h"
#include "metrics.h"
#include "scatter_svg.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <regex>

using app::DisplayImage;

namespace {
DisplayImage constant(int w, int h, float value) {
  DisplayImage image;
  image.width = w;
  image.height = h;
  image.rgb.assign(size_t(w) * h * 3, value);
  return image;
}
DisplayImage noisy(int w, int h, uint32_t seed, float amplitude) {
  DisplayImage image = constant(w, h, 0.5f);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-amplitude, amplitude);
  for (float& v : image.rgb) v = std::clamp(v + noise(rng), 0.0f, 1.0f);
  return image;
}
std::vector<uint8_t> toRgba8(const DisplayImage& image) {
  std::vector<uint8_t> out(size_t(image.width) * image.height * 4, 255);
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p)
    for (int c = 0; c < 3; ++c) out[p * 4 + c] = uint8_t(std::lround(image.rgb[p * 3 + c] * 255.0f));
  return out;
}
}  // namespace

TEST(Metrics, IdenticalImagesAreCappedAndPerfect) {
  const DisplayImage a = noisy(32, 32, 1, 0.3f);
  const app::ErrorMetrics m = app::compare(a, a, {});
  EXPECT_EQ(m.mse, 0.0);
  EXPECT_EQ(m.psnrDb, app::kPsnrCapDb);
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);
  EXPECT_EQ(m.maxAbsError, 0.0);
}

TEST(Metrics, UniformOffsetGivesKnownMsePsnrAndMaxError) {
  const app::ErrorMetrics m = app::compare(constant(16, 16, 0.6f), constant(16, 16, 0.5f), {});
  EXPECT_NEAR(m.mse, 0.01, 1e-6);
  EXPECT_NEAR(m.psnrDb, 20.0, 1e-3);
  EXPECT_NEAR(m.maxAbsError, 0.1, 1e-6);
}

TEST(Metrics, EdgePsnrCountsOnlyMaskedPixelsAndInteriorPsnrTheRest) {
  DisplayImage a = constant(16, 16, 0.5f), b = constant(16, 16, 0.5f);
  std::vector<uint8_t> mask(256, 0);
  for (int i = 0; i < 16; ++i) {  // error only on masked pixels: 0.2 off
    mask[i * 16 + 3] = 1;
    for (int c = 0; c < 3; ++c) a.rgb[(i * 16 + 3) * 3 + c] = 0.7f;
  }
  const app::ErrorMetrics m = app::compare(a, b, mask);
  EXPECT_EQ(m.edgePixels, 16);
  EXPECT_NEAR(m.edgePsnrDb, 10.0 * std::log10(1.0 / 0.04), 1e-3);
  EXPECT_NEAR(m.psnrDb, 10.0 * std::log10(1.0 / (0.04 / 16.0)), 1e-3);
  // Off the mask nothing differs: the interior is exact (capped), and it alone sees an interior blur.
  EXPECT_EQ(m.interiorPixels, 240);
  EXPECT_EQ(m.interiorPsnrDb, app::kPsnrCapDb);
  for (int c = 0; c < 3; ++c) a.rgb[(5 * 16 + 9) * 3 + c] = 0.6f;  // one interior pixel 0.1 off
  const app::ErrorMetrics blurred = app::compare(a, b, mask);
  EXPECT_NEAR(blurred.interiorPsnrDb, 10.0 * std::log10(1.0 / (0.01 / 240.0)), 1e-3);
  EXPECT_EQ(blurred.edgePsnrDb, m.edgePsnrDb);
  // pixelErrors (regress's lag figure) gives the same per-pixel figures and leaves the SSIM out.
  const app::ErrorMetrics pixels = app::pixelErrors(a, b, mask);
  EXPECT_EQ(pixels.edgePsnrDb, blurred.edgePsnrDb);
  EXPECT_EQ(pixels.interiorPsnrDb, blurred.interiorPsnrDb);
  EXPECT_EQ(pixels.maxAbsError, blurred.maxAbsError);
  EXPECT_LT(blurred.ssim, 1.0);
  EXPECT_EQ(pixels.ssim, 0.0);
}

TEST(Metrics, SsimIsSymmetricAndFallsWithNoise) {
  const DisplayImage clean = noisy(48, 48, 3, 0.2f);
  DisplayImage light = clean, heavy = clean;
  std::mt19937 rng(9);
  std::normal_distribution<float> n(0.0f, 1.0f);
  for (size_t i = 0; i < clean.rgb.size(); ++i) {
    const float e = n(rng);
    light.rgb[i] = std::clamp(clean.rgb[i] + 0.02f * e, 0.0f, 1.0f);
    heavy.rgb[i] = std::clamp(clean.rgb[i] + 0.2f * e, 0.0f, 1.0f);
  }
  EXPECT_NEAR(app::ssim(clean, light), app::ssim(light, clean), 1e-12);
  EXPECT_GT(app::ssim(clean, light), app::ssim(clean, heavy));
  EXPECT_LT(app::ssim(clean, heavy), 0.9);
  // A constant shift keeps structure: SSIM stays near 1 while PSNR drops.
  DisplayImage shifted = clean;
  for (float& v : shifted.rgb) v = std::min(1.0f, v + 0.05f);
  EXPECT_GT(app::ssim(clean, shifted), 0.95);
}

TEST(Metrics, PsnrAgreesWithOpenImageIo) {
  const DisplayImage a = noisy(64, 48, 5, 0.25f), b = noisy(64, 48, 6, 0.25f);
  const auto dir = std::filesystem::temp_directory_path() / "retroaa_metrics_test";
  std::filesystem::create_directories(dir);
  const std::string pathA = (dir / "a.png").string(), pathB = (dir / "b.png").string();
  app::writeImage8(pathA, 64, 48, toRgba8(a));
  app::writeImage8(pathB, 64, 48, toRgba8(b));
  int w = 0, h = 0;
  DisplayImage readA, readB;
  readA.rgb = app::readImageRgb(pathA, w, h), readA.width = w, readA.height = h;
  readB.rgb = app::readImageRgb(pathB, w, h), readB.width = w, readB.height = h;
  const double ours = app::compare(readA, readB, {}).psnrDb;
  // OpenImageIO compares all channels; ours are RGB, so compare the RGB channels only.
  OIIO::ImageBuf imageA(pathA), imageB(pathB);
  OIIO::ImageBuf rgbA = OIIO::ImageBufAlgo::channels(imageA, 3, {0, 1, 2});
  OIIO::ImageBuf rgbB = OIIO::ImageBufAlgo::channels(imageB, 3, {0, 1, 2});
  const auto theirs = OIIO::ImageBufAlgo::compare(rgbA, rgbB, 1.0f, 1.0f);
  std::printf("PSNR: retroaa %.4f dB, OpenImageIO %.4f dB\n", ours, theirs.PSNR);
  EXPECT_NEAR(ours, theirs.PSNR, 0.01);
}

TEST(Metrics, HeatmapIsBlackWhereEqualAndBrightWhereWrong) {
  DisplayImage a = constant(16, 16, 0.5f), b = constant(16, 16, 0.5f);
  for (int c = 0; c < 3; ++c) a.rgb[(5 * 16 + 5) * 3 + c] = 1.0f;
  const std::vector<uint8_t> heat = app::errorHeatmap(a, b);
  EXPECT_EQ(heat[0], 0);
  EXPECT_EQ(heat[(5 * 16 + 5) * 4], 255);
}

TEST(ScatterSvg, EveryPointIsLabelledWithoutOverlapAndTheTargetIsDrawn) {
  // The demo sweep's crowd: fourteen settings within 5 ms and 6 dB of each other.
  const char* names[] = {"off",         "fxaa",           "resolve",      "resolve/front", "resolve/back",
                         "resolve/fso", "resolve/window", "resolve/mean", "resolve+fxaa",  "coverage",
                         "edge",        "adaptive",       "aggregate",    "per-sample"};
  std::vector<app::ScatterPoint> points;
  for (int i = 0; i < 14; ++i) points.push_back({names[i], 1.0 + 0.3 * i, 14.8 + 0.4 * (i % 5) + 0.05 * i, i == 10});
  const std::string svg = app::svgScatter(points, {"GPU ms", "edge PSNR dB", 17.5, "chosen"});
  const std::regex label("<text x=\"([0-9.]+)\" y=\"([0-9.]+)\" class=\"label[^\"]*\">([^<]+)</text>");
  struct Box {
    double x0, y0, x1, y1;
  };
  std::vector<Box> boxes;
  std::vector<std::string> labelled;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), label); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    boxes.push_back({x, y - 10, x + 6.0 * double((*it)[3].length()), y + 2});
    labelled.push_back((*it)[3]);
  }
  EXPECT_EQ(labelled.size(), points.size()) << svg;
  for (const app::ScatterPoint& p : points)
    EXPECT_NE(std::find(labelled.begin(), labelled.end(), p.label), labelled.end()) << p.label;
  for (size_t a = 0; a < boxes.size(); ++a)
    for (size_t b = a + 1; b < boxes.size(); ++b)
      EXPECT_FALSE(boxes[a].x0 < boxes[b].x1 && boxes[b].x0 < boxes[a].x1 && boxes[a].y0 < boxes[b].y1 &&
                   boxes[b].y0 < boxes[a].y1)
          << labelled[a] << " overlaps " << labelled[b];
  EXPECT_NE(svg.find("class=\"target\""), std::string::npos);
  EXPECT_NE(svg.find(">target 17.5</text>"), std::string::npos);
  EXPECT_NE(svg.find("Pareto front: no cheaper point is better"), std::string::npos);
  EXPECT_NE(svg.find(">chosen</text>"), std::string::npos);
}
