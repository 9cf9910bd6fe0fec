// `coverage` (Pettineo, "Deferred MSAA"): the filter on hand-written depth sub-samples, and its
// failure mode on a grazing plane.
#include "test_support.h"

#include <map>

using namespace testing_support;

namespace {

constexpr int kWidth = 16, kHeight = 8;

struct CoverageFixture {
  SyntheticFrame frame{kWidth, kHeight};
  std::unique_ptr<patch::RetroaaHooks> hooks;
  std::vector<uint8_t> input;  // RGBA8, GL rows

  explicit CoverageFixture(const std::vector<uint8_t>& display, float pixelDepth = 0.5f, float tolerance = 2.0f)
      : input(display) {
    retroaa::Config config;
    config.method = retroaa::Method::Coverage;
    config.coverageTolerance = tolerance;
    hooks = frame.attach(config);
    if (!hooks) throw std::runtime_error("the patch did not attach");
    const host::HostTargets& t = frame.renderer->targets();
    glTextureSubImage2D(t.displayTexture, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, display.data());
    std::vector<uint32_t> depth(kWidth * kHeight, uint32_t(pixelDepth * 0xFFFFFF) << 8);
    glTextureSubImage2D(t.depthStencil, 0, 0, 0, kWidth, kHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth.data());
  }
  std::vector<uint8_t> filter(const char* sampleDepth) {
    return runPrepassFilter(hooks->plugin(), frame.renderer->targets().displayTexture, kWidth, kHeight,
                            std::string("gl_FragDepth = ") + sampleDepth + ";");
  }
};

std::vector<uint8_t> columns(uint8_t left, uint8_t right, int split) {
  std::vector<uint8_t> image(kWidth * kHeight * 4, 255);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) image[(y * kWidth + x) * 4 + c] = x < split ? left : right;
  return image;
}

}  // namespace

TEST(CoverageFilter, HalfCoveredSilhouettePixelBlendsByItsCoverage) {
  // Pixel column 7 is the object's last; its samples right of the centre see the far background.
  CoverageFixture fixture(columns(40, 220, 8));
  const std::vector<uint8_t> out = fixture.filter("(x == 7 && position.x > 0.5) ? 1.0 : 0.5");
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const int value = out[(y * kWidth + x) * 4];
      if (x == 7)
        EXPECT_NEAR(value, 255 * linearToSrgb(0.5f * (srgbToLinear(40 / 255.0f) + srgbToLinear(220 / 255.0f))), 3)
            << "blended half way to the neighbour (covered fraction 1/2), in linear light";
      else
        EXPECT_EQ(value, x < 8 ? 40 : 220) << x << "," << y;
    }
  }
}

TEST(CoverageFilter, TheTapRunsOnlyOnThePixelsItBlends) {
  // Column 7 half covered, as above: the depth test marks its pixels and discards the rest; the tap runs on
  // the marked ones alone and writes them in place. One draw with an early return passed every pixel once.
  CoverageFixture fixture(columns(40, 220, 8));
  retroaa::Plugin& plugin = fixture.hooks->plugin();
  writePerSample(plugin.prepassFramebuffer(), kWidth, kHeight,
                 "gl_FragDepth = (x == 7 && position.x > 0.5) ? 1.0 : 0.5;");
  ASSERT_TRUE(plugin.resolve({verticalFovFor(0.8f, kWidth, kHeight), 0.1f, 100.0f}));
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  ASSERT_TRUE(plugin.post());
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samplesPassed = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samplesPassed);
  glDeleteQueries(1, &query);
  EXPECT_EQ(samplesPassed, uint64_t(2 * kHeight)) << "column 7 marked, then blended";
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(CoverageFilter, QuarterCoverageBlendsAQuarter) {
  CoverageFixture fixture(columns(40, 220, 8));
  // Only the rightmost sample of the pattern (largest x) sees the background.
  const std::vector<uint8_t> out = fixture.filter("(x == 7 && position.x > 0.8) ? 1.0 : 0.5");
  const float quarter = 255 * linearToSrgb(0.75f * srgbToLinear(40 / 255.0f) + 0.25f * srgbToLinear(220 / 255.0f));
  for (int y = 1; y < kHeight - 1; ++y) EXPECT_NEAR(out[(y * kWidth + 7) * 4], quarter, 3);
}

TEST(CoverageFilter, FlatInteriorGivesBackTheInputExactly) {
  std::vector<uint8_t> noise(kWidth * kHeight * 4);
  for (size_t i = 0; i < noise.size(); ++i) noise[i] = uint8_t((i * 2654435761u) >> 13);
  CoverageFixture fixture(noise);
  EXPECT_EQ(fixture.filter("0.5"), noise);
}

TEST(CoverageFilter, GrazingPlaneRaisesFalseEdgesOnlyWithATightTolerance) {
  // The seed's own failure mode. A plane 5 m away seen at a grazing angle: across the pixel its depth
  // changes by ~3 footprints (1/d linear in screen y, as perspective makes it) although no edge is
  // there. A tolerance tight enough flags the farther samples but not the nearer ones (the depth
  // profile is convex), so the flagged samples sit on one side and the pixel blends. (When both sides
  // are flagged their offsets cancel and the filter leaves the pixel alone.) The image has one-pixel
  // horizontal stripes, so any blend shows. llvmpipe interpolates depth once per pixel for all samples,
  // so its own renders cannot show this: the sample depths are written by hand, log-encoded as the
  // synthetic host stores them (near 0.1 m, far 100 m).
  std::vector<uint8_t> stripes(kWidth * kHeight * 4, 255);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) stripes[(y * kWidth + x) * 4 + c] = (y % 2) ? 200 : 30;
  const char* grazing = "log2((1.0 / (0.2 + 0.03 * (position.y - 0.5))) / 0.1) / log2(1000.0)";
  const float pixelDepth = std::log2(5.0f / 0.1f) / std::log2(1000.0f);
  std::map<float, int> changed;
  for (float tolerance : {0.05f, 0.5f, 1.0f, 1.15f, 1.5f, retroaa::Config{}.coverageTolerance}) {
    CoverageFixture fixture(stripes, pixelDepth, tolerance);
    const std::vector<uint8_t> out = fixture.filter(grazing);
    int count = 0;
    for (size_t p = 0; p < out.size() / 4; ++p) count += out[p * 4] != stripes[p * 4];
    changed[tolerance] = count;
    std::printf("grazing plane, coverage tolerance %.2f: %d of %d pixels blended\n", tolerance, count,
                kWidth * kHeight);
  }
  EXPECT_EQ(changed[retroaa::Config{}.coverageTolerance], 0);
  int worst = 0;
  for (const auto& [tolerance, count] : changed) worst = std::max(worst, count);
  // Some tighter tolerance blurs the whole plane (the top and bottom rows blend with their own
  // stripe, the tap being clamped at the image border).
  EXPECT_GE(worst, kWidth * (kHeight - 2));
}

TEST(Coverage, HoldsOnlyADepthTargetAndLightsOncePerPixel) {
  PatchedHost host("default", 64, 48);
  host.render("coverage");
  const retroaa::Stats stats = host.hooks->plugin().waitForStats();
  EXPECT_EQ(stats.evaluationsPerPixel(), 1.0);
  ASSERT_EQ(stats.samples, 4);
  // D24S8 × 4 samples, the post copy and the stencil marking the pixels the filter blends
  EXPECT_EQ(stats.bytesHeld, uint64_t(64 * 48) * (4u * 4u + 4u + 1u));
  EXPECT_EQ(host.hooks->plugin().geometryFramebuffer(), host.renderer->targets().gbufferFramebuffer);
  host.render("resolve+coverage");  // reuses the G-buffer's depth: no prepass
  EXPECT_EQ(host.hooks->plugin().prepassFramebuffer(), 0u);
}
