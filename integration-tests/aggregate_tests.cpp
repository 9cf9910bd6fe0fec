// `aggregate` (Crassin et al., AGAA): clustering on hand-written sample sets, the equivalence with
// per-sample when every sample is its own aggregate, and the budget on the demo scene.
#include "test_support.h"

#include <numeric>

using namespace testing_support;

namespace {

constexpr int kWidth = 16, kHeight = 8;

retroaa::Config aggregate(int count, float threshold = 0.1f) {
  retroaa::Config config;
  config.method = retroaa::Method::Aggregate;
  config.aggregateCount = count;
  config.aggregateThreshold = threshold;
  return config;
}

std::vector<std::vector<SyntheticSample>> everywhere(const std::vector<SyntheticSample>& pixel) {
  return std::vector<std::vector<SyntheticSample>>(kWidth * kHeight, pixel);
}

}  // namespace

TEST(AggregateClustering, TwoPlanesAtDifferentDepthsSplitExactly) {
  SyntheticFrame frame(kWidth, kHeight);
  const glm::vec3 red(1, 0, 0), blue(0, 0, 1);
  auto hooks =
      frame.run(aggregate(2), everywhere({surfaceSample(10, {0, 0, 1}, red), surfaceSample(10, {0, 0, 1}, red),
                                          surfaceSample(20, {0, 0, 1}, blue), surfaceSample(20, {0, 0, 1}, blue)}));
  for (uint8_t c : hooks->plugin().readSliceCounts()) ASSERT_EQ(c, 2);
  // Light = albedo, weighted by coverage: half red, half blue.
  for (const glm::vec4& light : frame.read(frame.renderer->targets().lightTexture)) {
    ASSERT_NEAR(light.r, 0.5f, 2e-3f);
    ASSERT_NEAR(light.b, 0.5f, 2e-3f);
  }
}

TEST(AggregateClustering, CreaseSplitsByNormal) {
  SyntheticFrame frame(kWidth, kHeight);
  const glm::vec3 side = glm::normalize(glm::vec3(1, 0, 1));
  auto hooks =
      frame.run(aggregate(2),
                everywhere({surfaceSample(10), surfaceSample(10), surfaceSample(10, side), surfaceSample(10, side)}));
  for (uint8_t c : hooks->plugin().readSliceCounts()) ASSERT_EQ(c, 2);
  auto gentle = frame.run(aggregate(2), everywhere({surfaceSample(10), surfaceSample(10),
                                                    surfaceSample(10, glm::normalize(glm::vec3(0.1f, 0, 1))),
                                                    surfaceSample(10, glm::normalize(glm::vec3(0.1f, 0, 1)))}));
  for (uint8_t c : gentle->plugin().readSliceCounts()) ASSERT_EQ(c, 1);  // 6° apart: one surface
}

TEST(AggregateClustering, FarAndNearShipsBehaveAlikeRelativeToTheirFootprint) {
  SyntheticFrame frame(kWidth, kHeight);
  for (float gapInFootprints : {0.5f, 10.0f}) {
    std::vector<uint8_t> reference;
    for (float depth : {10.0f, 10000.0f}) {
      const float gap = gapInFootprints * depth * std::tan(1.0f / kWidth);
      auto hooks = frame.run(aggregate(2), everywhere({surfaceSample(depth), surfaceSample(depth),
                                                       surfaceSample(depth + gap), surfaceSample(depth + gap)}));
      const std::vector<uint8_t> counts = hooks->plugin().readSliceCounts();
      if (reference.empty()) reference = counts;
      EXPECT_EQ(counts, reference) << gapInFootprints << " footprints at " << depth << " m";
      EXPECT_EQ(counts[0], gapInFootprints < 1.0f ? 1 : 2) << gapInFootprints << " footprints at " << depth << " m";
    }
  }
}

TEST(AggregateClustering, BackgroundIsItsOwnSliceAndKeepsTheSky) {
  SyntheticFrame frame(kWidth, kHeight);
  auto hooks = frame.run(aggregate(2), everywhere({surfaceSample(10, {0, 0, 1}, glm::vec3(1)), backgroundSample(),
                                                   surfaceSample(10, {0, 0, 1}, glm::vec3(1)), backgroundSample()}));
  for (uint8_t c : hooks->plugin().readSliceCounts()) ASSERT_EQ(c, 2);
  // Light = albedo: geometry slice white at weight 1/2; the background slice has albedo 0.
  for (const glm::vec4& light : frame.read(frame.renderer->targets().lightTexture)) ASSERT_NEAR(light.g, 0.5f, 2e-3f);
}

TEST(AggregateClustering, ToksvigLowersGlossWhereNormalsSpread) {
  SyntheticFrame frame(kWidth, kHeight);
  const glm::vec3 left = glm::normalize(glm::vec3(-0.5f, 0, 1)), right = glm::normalize(glm::vec3(0.5f, 0, 1));
  SyntheticSample a = surfaceSample(10, left), b = surfaceSample(10, right);
  a.attachments[2].w = b.attachments[2].w = 0.9f;
  retroaa::Config config = aggregate(1, 10.0f);
  config.restoreGBufferAfterShade = false;  // read the aggregate the slice lit, not the resolved G-buffer
  auto hooks = frame.run(config, everywhere({a, b, a, b}));
  for (uint8_t c : hooks->plugin().readSliceCounts()) ASSERT_EQ(c, 1);
  for (const glm::vec4& normal : frame.read(frame.renderer->targets().normal)) {
    ASSERT_NEAR(glm::length(glm::vec3(normal)), 1.0f, 2e-3f);
    ASSERT_NEAR(normal.z, 1.0f, 2e-3f);  // the mean direction
    ASSERT_LT(normal.w, 0.6f);           // exponent 2^10 over a ±27° cone falls to a few dozen
    ASSERT_GT(normal.w, 0.0f);
  }
}

TEST(Aggregate, EverySampleItsOwnAggregateEqualsPerSample) {
  // Pixels whose four samples are all distinct (depth and normal), with c = N and t = 0.
  SyntheticFrame frame(kWidth, kHeight);
  std::vector<std::vector<SyntheticSample>> pixels;
  for (int p = 0; p < kWidth * kHeight; ++p) {
    std::vector<SyntheticSample> samples;
    for (int s = 0; s < 4; ++s)
      samples.push_back(surfaceSample(5.0f + 7.0f * s + 0.1f * p,
                                      glm::normalize(glm::vec3(0.3f * s - 0.5f, 0.1f * (p % 3), 1)),
                                      glm::vec3(0.1f + 0.2f * s, 0.05f * (p % 7), 0.9f - 0.2f * s)));
    pixels.push_back(samples);
  }
  retroaa::Config perSample;
  perSample.method = retroaa::Method::PerSample;
  frame.run(perSample, pixels);
  const std::vector<glm::vec4> reference = frame.read(frame.renderer->targets().lightTexture);
  auto hooks = frame.run(aggregate(4, 0.0f), pixels);
  for (uint8_t c : hooks->plugin().readSliceCounts()) ASSERT_EQ(c, 4);
  const std::vector<glm::vec4> result = frame.read(frame.renderer->targets().lightTexture);
  for (size_t i = 0; i < result.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(result[i][c], reference[i][c], 2e-3f) << "pixel " << i;
}

TEST(Aggregate, DemoSceneWithinTheBudgetAndNearPerSampleOnEdges) {
  PatchedHost host("default", 320, 240);
  const ScoringTruth truth = host.scoringTruth(8);
  const double perSample = truth.score(host.render("per-sample")).edgePsnrDb;
  host.render("edge");  // the coverage detector's edge fraction
  const std::vector<uint8_t> edgeCounts = host.hooks->plugin().readSliceCounts();
  const double edgeFraction =
      double(std::count_if(edgeCounts.begin(), edgeCounts.end(), [](uint8_t c) { return c > 1; })) / edgeCounts.size();
  const double aggregateEdgePsnr = truth.score(host.render("aggregate")).edgePsnrDb;
  const retroaa::Stats stats = host.hooks->plugin().waitForStats();
  const std::vector<uint8_t> counts = host.hooks->plugin().readSliceCounts();
  std::printf(
      "aggregate c=2: %.4f evaluations/pixel (bound 1 + edge fraction = %.4f), edge PSNR %.2f dB vs per-sample %.2f "
      "dB\n",
      stats.evaluationsPerPixel(), 1.0 + edgeFraction, aggregateEdgePsnr, perSample);
  EXPECT_EQ(stats.lightingEvaluations, std::accumulate(counts.begin(), counts.end(), uint64_t(0)));
  for (uint8_t c : counts) ASSERT_LE(c, 3);  // c = 2 aggregates and the background's slice
  // Cheap as `edge`: the clustering's distance and `edge`'s coverage + plane test are different tests and
  // disagree on a few pixels either way (0.04 % of the demo's), hence a tenth of a percent.
  EXPECT_LE(stats.evaluationsPerPixel(), 1.0 + edgeFraction + 0.001);
  EXPECT_GE(aggregateEdgePsnr, perSample - 1.0);
}
