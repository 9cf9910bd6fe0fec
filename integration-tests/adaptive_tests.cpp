// `adaptive` (Holländer et al.): each metric on hand-written G-buffers, the forced case against
// per-sample, and the evaluation budget on the demo scene.
#include "pipeline/pipeline.h"
#include "test_support.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>

using namespace testing_support;

namespace {

constexpr int kWidth = 64, kHeight = 16;

class AdaptiveMetrics : public ::testing::Test {
 protected:
  // The per-pixel k of `adaptive` on `pixels` (bottom-up rows), lit with light = albedo · irradiance.
  std::vector<uint8_t> sampleCounts(const std::vector<std::vector<SyntheticSample>>& pixels,
                                    retroaa::Config config = {}, const std::string& irradiance = "1.0") {
    config.method = retroaa::Method::Adaptive;
    auto hooks = frame_.run(config, pixels, irradiance);
    samples_ = frame_.samples;
    evaluations_ = hooks->plugin().waitForStats().lightingEvaluations;
    return hooks->plugin().readSliceCounts();
  }
  std::vector<std::vector<SyntheticSample>> uniform(const std::vector<SyntheticSample>& pixel) {
    return std::vector<std::vector<SyntheticSample>>(kWidth * kHeight, pixel);
  }
  SyntheticFrame frame_{kWidth, kHeight};
  int samples_ = 0;
  uint64_t evaluations_ = 0;
};

}  // namespace

TEST_F(AdaptiveMetrics, FlatPlaneNeedsOneSample) {
  const auto counts =
      sampleCounts(uniform({surfaceSample(10), surfaceSample(10), surfaceSample(10), surfaceSample(10)}));
  for (uint8_t k : counts) ASSERT_EQ(k, 1);
  EXPECT_EQ(evaluations_, uint64_t(kWidth * kHeight));
}

TEST_F(AdaptiveMetrics, DepthStepNeedsEverySample) {
  // Far and near ships alike: the depth metric is measured in pixel footprints.
  for (float near : {10.0f, 10000.0f}) {
    const auto counts = sampleCounts(
        uniform({surfaceSample(near), surfaceSample(near), surfaceSample(near * 2), surfaceSample(near * 2)}));
    for (uint8_t k : counts) ASSERT_EQ(k, samples_) << "at " << near << " m";
  }
}

TEST_F(AdaptiveMetrics, SmallDepthSlopeIsScaleInvariant) {
  // A gently sloped plane: depths spread by a tenth of a footprint. k must not depend on distance.
  std::vector<uint8_t> reference;
  for (float d : {10.0f, 1000.0f, 100000.0f}) {
    const float footprint = d * std::tan(1.0f / kWidth);
    const auto counts =
        sampleCounts(uniform({surfaceSample(d), surfaceSample(d + 0.1f * footprint),
                              surfaceSample(d + 0.2f * footprint), surfaceSample(d + 0.3f * footprint)}));
    if (reference.empty()) reference = counts;
    EXPECT_EQ(counts, reference) << "at " << d << " m";
    EXPECT_EQ(counts[0], 1);
  }
}

TEST_F(AdaptiveMetrics, NormalCreaseRefines) {
  const glm::vec3 tilted = glm::normalize(glm::vec3(0.7f, 0.0f, 0.7f));
  const auto counts = sampleCounts(
      uniform({surfaceSample(10), surfaceSample(10), surfaceSample(10, tilted), surfaceSample(10, tilted)}));
  for (uint8_t k : counts) ASSERT_GT(k, 1);
}

TEST_F(AdaptiveMetrics, LightingStepOnAFlatPlaneRefinesOnlyBesideIt) {
  // One flat plane of one albedo, lit dark on the left and bright on the right: geometry says 1, the
  // shading metric more, and only in the two columns beside the change.
  const SyntheticSample s = surfaceSample(10);
  const auto counts =
      sampleCounts(uniform({s, s, s, s}), {}, "gl_FragCoord.x < " + std::to_string(kWidth / 2) + ".0 ? 0.1 : 1.8");
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool besideEdge = x == kWidth / 2 - 1 || x == kWidth / 2;
      if (besideEdge)
        EXPECT_GT(counts[y * kWidth + x], 1) << x << "," << y;
      else
        EXPECT_EQ(counts[y * kWidth + x], 1) << x << "," << y;
    }
}

namespace {
// A flat plane, dark albedo left of column `split` and bright from it on; the pixels of column
// `inside` (if any) hold half dark, half bright samples.
std::vector<std::vector<SyntheticSample>> albedoStep(int split, int inside) {
  const SyntheticSample dark = surfaceSample(10, {0, 0, 1}, glm::vec3(0.05f)),
                        bright = surfaceSample(10, {0, 0, 1}, glm::vec3(0.9f));
  std::vector<std::vector<SyntheticSample>> pixels(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const SyntheticSample& s = x < split ? dark : bright;
      pixels[y * kWidth + x] = x == inside ? std::vector<SyntheticSample>{dark, dark, bright, bright}
                                           : std::vector<SyntheticSample>{s, s, s, s};
    }
  return pixels;
}
}  // namespace

TEST_F(AdaptiveMetrics, TextureContrastBetweenPixelsNeedsNoSamples) {
  // An albedo step on a pixel boundary: every pixel's samples hold one texel, so lighting more of them
  // changes nothing. Neighbours are compared at the pixel's own albedo: no refinement anywhere.
  const auto counts = sampleCounts(albedoStep(kWidth / 2, -1));
  for (int i = 0; i < kWidth * kHeight; ++i) ASSERT_EQ(counts[i], 1) << i % kWidth << "," << i / kWidth;
}

TEST_F(AdaptiveMetrics, TextureInsideAPixelRefinesThatPixelOnly) {
  // The step inside the pixels of one column: the texture term sees the albedo's range over the
  // samples; without it (scale 0) nothing does, since the first lit sample matches its neighbours.
  const int column = kWidth / 2;
  const auto counts = sampleCounts(albedoStep(column, column));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (x == column)
        EXPECT_EQ(counts[y * kWidth + x], samples_) << x << "," << y;
      else
        EXPECT_EQ(counts[y * kWidth + x], 1) << x << "," << y;
    }
  retroaa::Config noTexture;
  noTexture.adaptiveTextureScale = 0.0f;
  for (uint8_t k : sampleCounts(albedoStep(column, column), noTexture)) ASSERT_EQ(k, 1);
}

TEST_F(AdaptiveMetrics, GrazingPlaneNeedsOneSampleADepthStepStillEvery) {
  // A plane seen at a grazing angle, each sample at its own depth (inverse depth linear in screen x):
  // from 10 m to 60 m across the image, several footprints of depth inside every pixel. Its spread
  // about the mean is large, about the plane the neighbouring pixels continue nil: one sample.
  retroaa::Config config;
  config.method = retroaa::Method::Adaptive;
  config.adaptiveDepthScale = 4.0f;  // the quality setting of docs/methods/adaptive.md
  std::vector<float> positions;
  {
    auto hooks = frame_.attach(config);
    ASSERT_TRUE(hooks);
    GLint samples = 0;
    glBindFramebuffer(GL_FRAMEBUFFER, hooks->plugin().geometryFramebuffer());  // GL_SAMPLES is the bound one's
    glGetIntegerv(GL_SAMPLES, &samples);
    positions.assign(size_t(std::max(samples, 1)) * 2, 0.5f);
    retroaa::readSamplePositions(hooks->plugin().geometryFramebuffer(), positions);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  const int n = int(positions.size() / 2);
  ASSERT_GT(n, 1);
  auto plane = [&](float step) {
    std::vector<std::vector<SyntheticSample>> pixels(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        for (int s = 0; s < n; ++s) {
          const float screenX = float(x) + positions[2 * s];
          const float depth = 1.0f / (0.1f - (0.1f - 1.0f / 60.0f) * screenX / float(kWidth));
          pixels[y * kWidth + x].push_back(surfaceSample(positions[2 * s + 1] < 0.5f ? depth : depth * (1.0f + step)));
        }
    return pixels;
  };
  for (uint8_t k : sampleCounts(plane(0.0f), config)) ASSERT_EQ(k, 1);
  // The same plane with a 20 % depth step through every pixel (its upper samples farther): every sample.
  for (uint8_t k : sampleCounts(plane(0.2f), config)) ASSERT_EQ(k, samples_);
}

TEST(Adaptive, SampleOrderSpreadsOverThePixel) {
  // The standard 4× pattern: nearest the centre first, then the farthest from it, and so on.
  const std::vector<float> positions = {0.375f, 0.125f, 0.875f, 0.375f, 0.125f, 0.625f, 0.625f, 0.875f};
  const std::vector<int> order = retroaa::spreadingSampleOrder(positions);
  ASSERT_EQ(order.size(), 4u);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2, 3}));
  // The first two are on opposite sides of the centre.
  const glm::vec2 a(positions[2 * order[0]], positions[2 * order[0] + 1]),
      b(positions[2 * order[1]], positions[2 * order[1] + 1]);
  EXPECT_LT(glm::dot(a - glm::vec2(0.5f), b - glm::vec2(0.5f)), 0.0f);
}

TEST(Adaptive, ForcedToEverySampleEqualsPerSample) {
  PatchedHost host("default", 160, 120);
  const app::DisplayImage perSample = host.render("per-sample");
  retroaa::Config config;
  config.adaptiveMinSamples = 16;  // clamped to N in the shader: every pixel takes every sample
  const app::DisplayImage forced = host.render("adaptive", config);
  double worst = 0;
  for (size_t i = 0; i < forced.rgb.size(); ++i)
    worst = std::max<double>(worst, std::fabs(forced.rgb[i] - perSample.rgb[i]));
  EXPECT_LE(worst, 1.0 / 255.0 + 1e-6);
  EXPECT_EQ(host.hooks->plugin().waitForStats().evaluationsPerPixel(), double(host.hooks->plugin().stats().samples));
}

TEST(Adaptive, DemoSceneWithinTheBudgetNearPerSampleQuality) {
  PatchedHost host("default", 320, 240);
  const app::DisplayImage perSample = host.render("per-sample");
  const double perSampleEvaluations = host.hooks->plugin().waitForStats().evaluationsPerPixel();
  const app::DisplayImage adaptive = host.render("adaptive");
  const retroaa::Stats stats = host.hooks->plugin().waitForStats();
  const std::vector<uint8_t> counts = host.hooks->plugin().readSliceCounts();
  const double psnr = app::compare(adaptive, perSample, {}).psnrDb;
  std::printf("adaptive: %.3f evaluations/pixel (%.1f %% of per-sample), PSNR vs per-sample %.2f dB\n",
              stats.evaluationsPerPixel(), 100.0 * stats.evaluationsPerPixel() / perSampleEvaluations, psnr);
  EXPECT_EQ(stats.lightingEvaluations, std::accumulate(counts.begin(), counts.end(), uint64_t(0)));
  EXPECT_LE(stats.evaluationsPerPixel(), 0.6 * perSampleEvaluations);
  EXPECT_GE(psnr, 40.0);
}

// The shading metric takes two of a pixel's four neighbours from its quad (common/quad_exchange.glsl)
// instead of fetching them: each pixel's partners across x and y, bit for bit, at an odd size (the last
// column's and row's partners are helper fragments, fetching at the clamped pixel) and on floats a
// difference would round (NaN, infinities, denormals, 1e30 beside 1e-30, negative zero).
TEST(QuadExchange, GivesEachPixelItsQuadPartnersValuesBitForBit) {
  PatchedHost host("default", 32, 24);
  constexpr int kW = 7, kH = 5;
  const float specials[] = {0.0f,
                            -0.0f,
                            1.0f,
                            -1.0f,
                            1e-40f,
                            -3e-39f,
                            3.4e38f,
                            1e30f,
                            1e-30f,
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(),
                            3.14159265f,
                            65504.0f,
                            1.0f / 3.0f};
  std::vector<float> values(kW * kH);
  for (size_t i = 0; i < values.size(); ++i)
    values[i] = i < std::size(specials) ? specials[i] : float(i) * 0.7310585f - 9.0f;
  GLuint input = 0, output = 0, framebuffer = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &input);
  glTextureStorage2D(input, 1, GL_R32F, kW, kH);
  glTextureSubImage2D(input, 0, 0, 0, kW, kH, GL_RED, GL_FLOAT, values.data());
  glCreateTextures(GL_TEXTURE_2D, 1, &output);
  glTextureStorage2D(output, 1, GL_RGBA32UI, kW, kH);
  glCreateFramebuffers(1, &framebuffer);
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, output, 0);
  ASSERT_EQ(glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  std::ifstream file(std::string(RETROAA_SOURCE_DIR) + "/shaders/common/quad_exchange.glsl");
  const std::string exchange((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(exchange.empty());
  const std::string source = "#version 450 core\n" + exchange + R"(
layout(binding = 0) uniform sampler2D uValues;
layout(location = 0) out uvec4 outPartners;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float own = texelFetch(uValues, clamp(pixel, ivec2(0), textureSize(uValues, 0) - 1), 0).r;
  int sideX = quadPartnerSideX(), sideY = quadPartnerSideY();
  vec2 acrossX = quadPartnerX(vec2(own, -own), sideX), acrossY = quadPartnerY(vec2(-own, own), sideY);
  outPartners = uvec4(floatBitsToUint(acrossX), floatBitsToUint(acrossY.y), uint(sideX + 2) | uint(sideY + 2) << 4u);
})";
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, kW, kH);
  glBindTextureUnit(0, input);
  drawWithFragment(source.c_str(), [](GLuint) {});
  std::vector<uint32_t> partners(size_t(kW) * kH * 4);
  glReadPixels(0, 0, kW, kH, GL_RGBA_INTEGER, GL_UNSIGNED_INT, partners.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &input);
  glDeleteTextures(1, &output);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  auto bits = [&values](int x, int y) {
    uint32_t b;
    std::memcpy(&b, &values[size_t(std::clamp(y, 0, kH - 1)) * kW + size_t(std::clamp(x, 0, kW - 1))], 4);
    return b;
  };
  auto side = [&partners](int x, int y, int shift) {
    return int((partners[(size_t(y) * kW + x) * 4 + 3] >> shift) & 15u) - 2;
  };
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const uint32_t* p = &partners[(size_t(y) * kW + x) * 4];
      const int sideX = side(x, y, 0), sideY = side(x, y, 4);
      ASSERT_TRUE(std::abs(sideX) == 1 && std::abs(sideY) == 1) << x << "," << y;
      const int partnerX = x + sideX, partnerY = y + sideY;
      // Partners pair up: a partner inside the image names this pixel back; one outside is a helper.
      if (partnerX >= 0 && partnerX < kW)
        EXPECT_EQ(side(partnerX, y, 0), -sideX) << x << "," << y;
      else
        EXPECT_EQ(partnerX, kW) << x << "," << y;
      if (partnerY >= 0 && partnerY < kH)
        EXPECT_EQ(side(x, partnerY, 4), -sideY) << x << "," << y;
      else
        EXPECT_EQ(partnerY, kH) << x << "," << y;
      EXPECT_EQ(p[0], bits(partnerX, y)) << "across x at " << x << "," << y;
      EXPECT_EQ(p[1], bits(partnerX, y) ^ 0x80000000u) << "across x, negated, at " << x << "," << y;
      EXPECT_EQ(p[2], bits(x, partnerY)) << "across y at " << x << "," << y;
    }
}
