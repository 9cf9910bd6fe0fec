// SMAA (Jimenez et al. 2012) on hand-written display images: a straight edge is blended towards its
// analytic coverage, flat images and a one-pixel checkerboard stay as they are, and FreeSpace Open's
// -aa_preset 3..6 select its presets; S2x; and post filters on an sRGB display. The lookup tables' own
// properties: plugin/tests/smaa_tables_tests.cpp.
#include "commands.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "methods/smaa.h"

using namespace testing_support;

namespace {

constexpr int kWidth = 96, kHeight = 48;

// SMAA's post pass on a display image written by hand (RGBA8, GL rows); returns the filtered display.
std::vector<uint8_t> smaaOf(const std::vector<uint8_t>& display, retroaa::SmaaQuality quality) {
  SyntheticFrame frame(kWidth, kHeight);
  retroaa::Config config;
  config.method = retroaa::Method::Smaa;
  config.smaaQuality = quality;
  auto hooks = frame.attach(config);
  if (!hooks) return {};
  const GLuint displayTexture = frame.renderer->targets().displayTexture;
  glTextureSubImage2D(displayTexture, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, display.data());
  EXPECT_TRUE(hooks->plugin().post());
  std::vector<uint8_t> out(display.size());
  glGetTextureImage(displayTexture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(out.size()), out.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return out;
}

std::vector<uint8_t> imageOf(const std::function<bool(int x, int y)>& white) {
  std::vector<uint8_t> image(size_t(kWidth) * kHeight * 4, 255);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) image[(size_t(y) * kWidth + x) * 4 + c] = white(x, y) ? 255 : 0;
  return image;
}

// `method`'s post passes on `image` (RGBA8, GL rows) written into the display by hand: the samples that
// passed every test (an occlusion query, which counts after the stencil test where llvmpipe's fragment
// counter counts before it), and the display afterwards.
std::pair<uint64_t, std::vector<uint8_t>> samplesPassedInPost(retroaa::Method method,
                                                              const std::vector<uint8_t>& image) {
  SyntheticFrame frame(kWidth, kHeight);
  retroaa::Config config;
  config.method = method;
  auto hooks = frame.attach(config);
  if (!hooks) {
    ADD_FAILURE() << "the plugin was not installed";
    return {};
  }
  const GLuint display = frame.renderer->targets().displayTexture;
  glTextureSubImage2D(display, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  EXPECT_TRUE(hooks->plugin().post());
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samplesPassed = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samplesPassed);
  glDeleteQueries(1, &query);
  std::vector<uint8_t> out(image.size());
  glGetTextureImage(display, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(out.size()), out.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return {samplesPassed, out};
}

// The fraction of pixel (x, y) below the line y = y0 + slope·x (exact: a trapezoid clipped to [0, 1]).
double coverageBelow(int x, int y, double y0, double slope) {
  // Integrate clamp(line(t) − y, 0, 1) over t in [x, x+1] numerically: fine enough at 1/4096.
  double sum = 0;
  constexpr int kSteps = 4096;
  for (int i = 0; i < kSteps; ++i) {
    const double t = x + (i + 0.5) / kSteps;
    sum += std::clamp(y0 + slope * t - y, 0.0, 1.0);
  }
  return sum / kSteps;
}

}  // namespace

TEST(Smaa, StraightEdgesBlendTowardsTheirAnalyticCoverage) {
  // White on one side of a shallow line (slope 1/8: stairs 8 pixels long, inside every preset's
  // search), aliased by a test at pixel centres; once nearly horizontal, once (transposed) nearly
  // vertical, so both search directions are exercised.
  const double offset = 20.3, slope = 1.0 / 8.0;
  for (bool vertical : {false, true}) {
    // (u, v): u runs along the line, v across it.
    auto along = [&](int x, int y) { return vertical ? y : x; };
    auto across = [&](int x, int y) { return vertical ? x : y; };
    const auto aliased =
        imageOf([&](int x, int y) { return across(x, y) + 0.5 < offset + slope * (along(x, y) + 0.5); });
    for (retroaa::SmaaQuality quality : {retroaa::SmaaQuality::Low, retroaa::SmaaQuality::High}) {
      const auto out = smaaOf(aliased, quality);
      ASSERT_FALSE(out.empty());
      double errorBefore = 0, errorAfter = 0;
      int edgePixels = 0;
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
          const int u = along(x, y), length = vertical ? kHeight : kWidth;
          if (u < 12 || u >= length - 12) continue;  // the line's stairs are cut off at the borders
          const double truth = coverageBelow(u, across(x, y), offset, slope);
          if (truth <= 0.0 || truth >= 1.0) continue;
          const size_t i = (size_t(y) * kWidth + x) * 4;
          errorBefore += std::abs(srgbToLinear(aliased[i] / 255.0f) - truth);
          errorAfter += std::abs(srgbToLinear(out[i] / 255.0f) - truth);
          ++edgePixels;
        }
      ASSERT_GT(edgePixels, 20);
      const double meanBefore = errorBefore / edgePixels, meanAfter = errorAfter / edgePixels;
      // Aliased, an edge pixel is off by 0.25 on average; SMAA's revectorisation gets within 0.06.
      EXPECT_LT(meanAfter, 0.06) << toString(quality) << (vertical ? " vertical" : " horizontal") << ": before "
                                 << meanBefore << ", after " << meanAfter;
      EXPECT_LT(meanAfter, meanBefore / 3) << toString(quality) << (vertical ? " vertical" : " horizontal");
    }
  }
}

TEST(Smaa, FlatImageIsLeftUnchanged) {
  std::vector<uint8_t> flat(size_t(kWidth) * kHeight * 4, 255);
  for (size_t i = 0; i < flat.size(); i += 4) flat[i] = 90, flat[i + 1] = 140, flat[i + 2] = 200;
  EXPECT_EQ(smaaOf(flat, retroaa::SmaaQuality::Ultra), flat);
}

TEST(Smaa, OnePixelCheckerboardIsLeftUnchangedByOrthogonalSearchesAndFlattenedByDiagonalOnes) {
  const auto checker = imageOf([](int x, int y) { return (x + y) % 2 == 0; });
  // Low and medium search only horizontal and vertical lines: every pixel has crossing edges on all
  // sides, so there is no line to revectorise and nothing is blended.
  for (retroaa::SmaaQuality quality : {retroaa::SmaaQuality::Low, retroaa::SmaaQuality::Medium})
    EXPECT_EQ(smaaOf(checker, quality), checker) << toString(quality);
  // High and ultra also search diagonals, and a checkerboard is indistinguishable from two crossing
  // 45° staircases of full length: the reference's diagonal search runs to its step limit, drops the
  // crossing edges ("no end found") and blends by the null diagonal pattern. The interior flattens to
  // its mean (linear 0.5). This is SMAA's behaviour, not ours to fix: stated here so a change shows.
  for (retroaa::SmaaQuality quality : {retroaa::SmaaQuality::High, retroaa::SmaaQuality::Ultra}) {
    const auto out = smaaOf(checker, quality);
    ASSERT_FALSE(out.empty());
    for (int y = 20; y < 28; ++y)
      for (int x = 40; x < 56; ++x)
        EXPECT_NEAR(srgbToLinear(out[(size_t(y) * kWidth + x) * 4] / 255.0f), 0.5, 0.02)
            << toString(quality) << " at " << x << "," << y;
  }
}

TEST(Smaa, TheWeightsPassRunsOnlyOnTheEdgesPassesPixelsAndTheBlendOnlyWhereWeightsAre) {
  // A white rectangle on black: the edges pass keeps the pixels whose left or lower neighbour differs,
  // the weights pass (the searches) runs on those alone through the stencil they marked; the blend
  // marks the pixels with weights of their own or from the neighbours they blend with and rewrites those
  // alone, in place (MarkedRewrite), so it passes twice as many samples as it changes pixels at most,
  // where one full-screen blend would pass every pixel. Counted after the stencil test by an occlusion
  // query, which llvmpipe's fragment counter is not (it counts before the test).
  const int left = 20, right = 60, bottom = 10, top = 30;
  const auto image = imageOf([&](int x, int y) { return x >= left && x < right && y >= bottom && y < top; });
  int edgePixels = 0;
  for (int y = 1; y < kHeight; ++y)
    for (int x = 1; x < kWidth; ++x) {
      const size_t at = (size_t(y) * kWidth + x) * 4;
      if (image[at] != image[at - 4] || image[at] != image[at - size_t(kWidth) * 4]) ++edgePixels;
    }
  ASSERT_EQ(edgePixels, 2 * (top - bottom) + 2 * (right - left) - 1);
  const auto [samplesPassed, out] = samplesPassedInPost(retroaa::Method::Smaa, image);
  ASSERT_GE(samplesPassed, uint64_t(2 * edgePixels));
  const uint64_t blendSamples = samplesPassed - uint64_t(2 * edgePixels);  // its marking and its rewrite
  EXPECT_EQ(blendSamples % 2, 0u) << "edges " << edgePixels << " + weights " << edgePixels << " + blend "
                                  << blendSamples;
  int changed = 0;
  for (size_t i = 0; i < out.size(); i += 4) changed += out[i] != image[i];
  EXPECT_GT(changed, 0) << "the rectangle's corners blend";
  EXPECT_GE(blendSamples / 2, uint64_t(changed));
  EXPECT_LT(blendSamples / 2, uint64_t(4 * edgePixels)) << "the blend ran beyond the edges";
}

TEST(Fxaa, TheSearchRunsOnlyOnPixelsThatPassTheContrastTest) {
  // The same rectangle: FXAA's contrast test (N, S, E, W and the centre, clamped at the borders) passes
  // where a 4-neighbour differs. The first draw marks those pixels and discards the rest; the second, the
  // search and blend, runs on them alone. One draw with an early return would pass every pixel once.
  const int left = 20, right = 60, bottom = 10, top = 30;
  const auto image = imageOf([&](int x, int y) { return x >= left && x < right && y >= bottom && y < top; });
  const auto at = [&](int x, int y) {
    return image[(size_t(std::clamp(y, 0, kHeight - 1)) * kWidth + size_t(std::clamp(x, 0, kWidth - 1))) * 4];
  };
  int filtered = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (at(x - 1, y) != at(x, y) || at(x + 1, y) != at(x, y) || at(x, y - 1) != at(x, y) || at(x, y + 1) != at(x, y))
        ++filtered;
  // The rectangle's border (its corners once) and the ring just outside it (no corners).
  ASSERT_EQ(filtered, 2 * (top - bottom) + 2 * (right - left) - 4 + 2 * (top - bottom) + 2 * (right - left));
  const auto [samplesPassed, out] = samplesPassedInPost(retroaa::Method::Fxaa, image);
  EXPECT_EQ(samplesPassed, uint64_t(2 * filtered)) << "marked " << filtered << " + filtered " << filtered;
  // Only those pixels change: the flat ones are not written at all.
  int changed = 0;
  for (size_t i = 0; i < out.size(); i += 4) changed += out[i] != image[i];
  EXPECT_GT(changed, 0);
  EXPECT_LE(changed, filtered);
}

TEST(Smaa, FsoAaPresetsThreeToSixSelectSmaaPresets) {
  const retroaa::SmaaQuality expected[] = {retroaa::SmaaQuality::Low, retroaa::SmaaQuality::Medium,
                                           retroaa::SmaaQuality::High, retroaa::SmaaQuality::Ultra};
  for (int preset = 3; preset <= 6; ++preset) {
    retroaa::Config config;
    std::vector<std::string> warnings;
    ASSERT_TRUE(retroaa::applyFsoFlag(config, "-aa_preset", std::to_string(preset), warnings));
    EXPECT_EQ(config.method, retroaa::Method::Smaa);
    EXPECT_EQ(config.smaaQuality, expected[preset - 3]);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
  }
}

TEST(SmaaS2x, SubsampleIndicesFollowTheReferencesS2xConvention) {
  // GL's standard 2× positions (0.75, 0.75) and (0.25, 0.25) sit, in the shaders' mirrored frame, where
  // the reference's D3D 2× samples (+¼, +¼) and (−¼, −¼) do: rows (1, 1, 1, 0) and (2, 2, 2, 0).
  EXPECT_EQ(retroaa::smaaSubsampleIndices(0.75f, 0.75f), (std::array<float, 4>{1, 1, 1, 0}));
  EXPECT_EQ(retroaa::smaaSubsampleIndices(0.25f, 0.25f), (std::array<float, 4>{2, 2, 2, 0}));
  EXPECT_EQ(retroaa::smaaSubsampleIndices(0.5f, 0.5f), (std::array<float, 4>{0, 0, 0, 0}));
  // Off-grid positions take the nearest row: llvmpipe's 4× sample 0 at (0.375, 0.125).
  EXPECT_EQ(retroaa::smaaSubsampleIndices(0.375f, 0.125f), (std::array<float, 4>{4, 6, 2, 0}));
}

TEST(SmaaS2x, LightsTheCentredPairOfSamples) {
  // GL's standard 2× pattern: both samples.
  EXPECT_EQ(retroaa::smaaS2xSamplePair({0.75f, 0.75f, 0.25f, 0.25f}), (std::array<int, 2>{0, 1}));
  // llvmpipe's 4× pattern: samples 0 and 1 average to (0.625, 0.25), a quarter pixel off; 0 and 3 are
  // centred (as are 1 and 2; the lower indices win).
  EXPECT_EQ(retroaa::smaaS2xSamplePair({0.375f, 0.125f, 0.875f, 0.375f, 0.125f, 0.625f, 0.625f, 0.875f}),
            (std::array<int, 2>{0, 3}));
  // A centred pair farther apart wins over a closer centred one.
  EXPECT_EQ(retroaa::smaaS2xSamplePair({0.4f, 0.5f, 0.6f, 0.5f, 0.1f, 0.1f, 0.9f, 0.9f}), (std::array<int, 2>{2, 3}));
}

TEST(SmaaS2x, LightsTwoSamplesPerPixelAndSitsBetweenSmaaAndEdgeInQuality) {
  PatchedHost host("default", 240, 180);
  const ScoringTruth truth = host.scoringTruth(8);
  const app::ErrorMetrics smaa = truth.score(host.render("smaa"));
  const app::ErrorMetrics s2x = truth.score(host.render("smaa-s2x@samples=2"));
  const retroaa::Stats stats = host.hooks->plugin().waitForStats();
  EXPECT_EQ(stats.lightingEvaluations, 2u * stats.pixels) << "both slices light every pixel";
  EXPECT_EQ(stats.slices, 2);
  EXPECT_TRUE(host.hooks->lastError().empty()) << host.hooks->lastError();
  const app::ErrorMetrics edge = truth.score(host.render("edge@samples=2"));
  std::printf("edge PSNR: smaa %.2f, smaa-s2x %.2f, edge@2 %.2f dB\n", smaa.edgePsnrDb, s2x.edgePsnrDb,
              edge.edgePsnrDb);
  EXPECT_GT(s2x.edgePsnrDb, smaa.edgePsnrDb + 0.5);
  EXPECT_LT(s2x.edgePsnrDb, edge.edgePsnrDb);
}

TEST(Smaa, ReconfiguringTheEdgeDetectionOrQualityRebuildsItsPasses) {
  // Each setting renders what a fresh plugin with it renders, whatever ran before it.
  PatchedHost host("default", 160, 120);
  const char* specs[] = {"smaa", "smaa@smaa_edge_detection=colour", "smaa@smaa_edge_detection=depth",
                         "smaa@smaa_quality=low", "smaa"};
  std::vector<std::vector<float>> sequential;
  for (const char* spec : specs) sequential.push_back(host.render(spec).rgb);
  for (size_t i = 0; i < std::size(specs); ++i) {
    PatchedHost fresh("default", 160, 120);
    EXPECT_EQ(fresh.render(specs[i]).rgb, sequential[i]) << specs[i];
  }
  EXPECT_NE(sequential[1], sequential[2]) << "colour and depth edges differ on the demo frame";
  EXPECT_NE(sequential[0], sequential[2]);
}

TEST(PostFilters, AnSrgbDisplayTextureIsFilteredByteForByteLikeAnRgba8One) {
  // post() works on the display's stored, gamma-encoded values. Read through an sRGB format they would
  // decode to linear (and FXAA rewrote every lit pixel of a third-party renderer's GL_SRGB8_ALPHA8
  // display, mean byte 14.15 → 7.99): the plugin filters the encoded bytes instead.
  const auto image = imageOf([](int x, int y) { return y + 0.5 < 20.3 + (x + 0.5) / 8.0; });
  for (const char* method : {"fxaa", "smaa"}) {
    std::vector<uint8_t> filtered[2];
    for (int srgb = 0; srgb < 2; ++srgb) {
      SyntheticFrame frame(kWidth, kHeight);
      retroaa::Description description;
      description.config = app::parseMethodSpec(method, {}).config;
      description.layout = patch::describeHostGBuffer(frame.renderer->targets());
      const StandInDisplay standIn(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, kWidth, kHeight);
      standIn.describeIn(description.layout);
      const GLuint display = standIn.texture;
      glTextureSubImage2D(display, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
      {
        auto plugin = retroaa::Plugin::create(description);
        ASSERT_TRUE(plugin) << plugin.error().message;
        ASSERT_TRUE(plugin.value()->post());
      }
      filtered[srgb].resize(image.size());
      glGetTextureImage(display, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(image.size()), filtered[srgb].data());
      EXPECT_NE(filtered[srgb], image) << method << (srgb ? " sRGB" : " RGBA8") << ": the edge was filtered";
    }
    EXPECT_EQ(filtered[1], filtered[0]) << method;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}
