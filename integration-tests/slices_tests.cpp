// Slices: `edge` and `per-sample` light extra samples through the host's unchanged lighting.
#include "test_support.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

using namespace testing_support;

namespace {
retroaa::Config edgeWith(retroaa::EdgeDetector detector) {
  retroaa::Config config;
  config.edgeDetector = detector;
  return config;
}
double maxChannelDifference(const app::DisplayImage& a, const app::DisplayImage& b) {
  double worst = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) worst = std::max<double>(worst, std::fabs(a.rgb[i] - b.rgb[i]));
  return worst;
}
std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

TEST(Slices, EdgeMarkingEveryPixelEqualsPerSample) {
  PatchedHost host("default", 160, 120);
  const app::DisplayImage perSample = host.render("per-sample");
  const app::DisplayImage everyPixel = host.render("edge", edgeWith(retroaa::EdgeDetector::EveryPixel));
  EXPECT_LE(maxChannelDifference(perSample, everyPixel), 1.0 / 255.0 + 1e-6);
  EXPECT_EQ(host.hooks->plugin().waitForStats().evaluationsPerPixel(), double(host.hooks->plugin().stats().samples));
}

// The slices past the first draw only the 16 x 16 tiles that hold their pixels (SliceRenderer::
// tilesWhereCountAtLeast), partial ones along the right and top edges here: each slice's occlusion query
// counts what its write drew, so a marked pixel no tile covers, or one two tiles draw, shows in the total.
TEST(Slices, SparseSlicesTilesCoverEveryMarkedPixelOnce) {
  PatchedHost host("default", 157, 119);
  for (const char* spec : {"edge", "adaptive", "aggregate"}) {
    host.render(spec);
    const retroaa::Stats stats = host.hooks->plugin().waitForStats();
    const std::vector<uint8_t> counts = host.hooks->plugin().readSliceCounts();
    ASSERT_EQ(counts.size(), size_t(157 * 119)) << spec;
    const uint64_t marked = std::count_if(counts.begin(), counts.end(), [](uint8_t c) { return c > 1; });
    EXPECT_GT(marked, 0u) << spec;
    EXPECT_LT(marked, counts.size() / 2) << spec;
    EXPECT_EQ(stats.lightingEvaluations, std::accumulate(counts.begin(), counts.end(), uint64_t(0))) << spec;
    // slice_tiles=off: full screens the stencil limits, the same image.
    const app::DisplayImage tiled = host.render(spec);
    retroaa::Config fullScreens;
    fullScreens.sliceTiles = false;
    EXPECT_EQ(host.render(spec, fullScreens).rgb, tiled.rgb) << spec;
  }
}

TEST(Slices, EdgeMatchesPerSampleAndCountsEvaluationsExactly) {
  PatchedHost host("default", 320, 240);
  const app::DisplayImage reference = host.render("per-sample");
  const int n = host.hooks->plugin().stats().samples;
  EXPECT_EQ(host.hooks->plugin().waitForStats().lightingEvaluations, uint64_t(320 * 240) * n);
  for (auto detector : {retroaa::EdgeDetector::Coverage, retroaa::EdgeDetector::Plane, retroaa::EdgeDetector::Depth}) {
    const app::DisplayImage edge = host.render("edge", edgeWith(detector));
    const retroaa::Stats stats = host.hooks->plugin().waitForStats();
    const std::vector<uint8_t> counts = host.hooks->plugin().readSliceCounts();
    const uint64_t edgePixels = std::count_if(counts.begin(), counts.end(), [](uint8_t c) { return c > 1; });
    const double edgeFraction = double(edgePixels) / counts.size();
    const double psnr = app::compare(edge, reference, {}).psnrDb;
    std::printf("edge/%s vs per-sample: PSNR %.2f dB, %.3f evaluations/pixel, edge fraction %.4f\n",
                retroaa::toString(detector), psnr, stats.evaluationsPerPixel(), edgeFraction);
    // Counts are either 1 or N, and the occlusion-query total is exactly their sum.
    for (uint8_t c : counts) ASSERT_TRUE(c == 1 || c == n) << int(c);
    EXPECT_EQ(stats.lightingEvaluations, std::accumulate(counts.begin(), counts.end(), uint64_t(0)));
    EXPECT_NEAR(stats.evaluationsPerPixel(), 1.0 + (n - 1) * edgeFraction, 1e-9);
    EXPECT_GT(edgeFraction, 0.01);
    EXPECT_LT(edgeFraction, 0.5);
    // Coverage and plane leave unmarked only samples of one plane with one normal, whose averaged
    // attributes light as their samples do; depth's fixed tolerance misses more.
    EXPECT_GE(psnr, detector == retroaa::EdgeDetector::Depth ? 38.0 : 58.0);
  }
}

TEST(Slices, PerSampleBeatsResolveAndFxaaOnSilhouettes) {
  PatchedHost host(testDataPath("scenes/light_behind_silhouette.json"), 240, 180);
  const ScoringTruth truth = host.scoringTruth(8);
  std::map<std::string, double> edgePsnr;
  for (const char* method : {"per-sample", "resolve", "fxaa", "off"})
    edgePsnr[method] = truth.score(host.render(method)).edgePsnrDb;
  std::printf("silhouette edge PSNR: per-sample %.2f, resolve %.2f, fxaa %.2f, off %.2f dB\n", edgePsnr["per-sample"],
              edgePsnr["resolve"], edgePsnr["fxaa"], edgePsnr["off"]);
  EXPECT_GT(edgePsnr["per-sample"], edgePsnr["resolve"] + 3.0);
  EXPECT_GT(edgePsnr["per-sample"], edgePsnr["fxaa"] + 3.0);
}

TEST(Slices, HostStencilBitsAreLeftAlone) {
  PatchedHost host("default", 96, 72);
  host.render("edge");
  // The host's depth-stencil holds a pattern of its own; a whole frame of `edge` must keep it.
  const GLuint depthStencil = host.renderer->targets().depthStencil;
  std::vector<uint32_t> pattern(96 * 72);
  for (size_t i = 0; i < pattern.size(); ++i) pattern[i] = 0x5Au | (uint32_t(i % 977) << 8);
  glTextureSubImage2D(depthStencil, 0, 0, 0, 96, 72, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, pattern.data());
  retroaa::Plugin& plugin = host.hooks->plugin();
  ASSERT_TRUE(plugin.resolve({0.9f}));
  ASSERT_TRUE(plugin.shade([](retroaa::GLuintHandle) {}));
  std::vector<uint32_t> after(pattern.size());
  glGetTextureImage(depthStencil, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, GLsizei(after.size() * 4), after.data());
  for (size_t i = 0; i < after.size(); ++i) ASSERT_EQ(after[i] & 0xFFu, 0x5Au) << "stencil changed at " << i;
}

TEST(Slices, WithoutStencilExportTheResultIsTheSame) {
  PatchedHost host("default", 128, 96);
  const app::DisplayImage withExport = host.render("edge");
  const uint64_t evaluations = host.hooks->plugin().waitForStats().lightingEvaluations;
  retroaa::Config config;
  config.method = retroaa::Method::Edge;
  retroaa::Description description;
  description.config = config;
  description.layout = patch::describeHostGBuffer(host.renderer->targets());
  description.disabledFeatures = retroaa::kFeatureStencilExport;
  auto plugin = retroaa::Plugin::create(description);
  ASSERT_TRUE(plugin) << plugin.error().message;
  EXPECT_NE(plugin.value()->warnings().front().find("no ARB_shader_stencil_export"), std::string::npos);
  // Render one frame by hand through the second plugin with the host's own lighting.
  host.renderer->setHooks(nullptr);
  struct Hooks : host::FrameHooks {
    retroaa::Plugin* plugin;
    GLuint modelPassFramebuffer(GLuint) override { return plugin->geometryFramebuffer(); }
    void modelPassEnd(const host::FrameView& v) override { plugin->resolve({v.verticalFovRadians}); }
    void lighting(const host::LightingPass& pass, GLuint) override {
      plugin->shade([&](GLuint t) { pass(t); });
    }
  } hooks;
  hooks.plugin = plugin.value().get();
  host.renderer->setHooks(&hooks);
  host.renderer->renderFrame(host.scene.camera);
  const auto withoutExport = app::DisplayImage::fromRgba8(128, 96, host.renderer->readDisplay());
  EXPECT_EQ(withExport.rgb, withoutExport.rgb);
  EXPECT_EQ(plugin.value()->waitForStats().lightingEvaluations, evaluations);
  host.renderer->setHooks(host.hooks.get());
}

TEST(Slices, TheHostCompilesItsStockLightingShadersUnchanged) {
  // The binary that ran the patched frames embeds the host's shader files byte for byte as they are in
  // engine-patch/common/shaders, and neither the patch nor the plugin carries a lighting shader.
  const std::string root = std::string(RETROAA_SOURCE_DIR);
  const auto& embedded = host::embeddedFiles();
  for (const char* file : {"light_ambient_directional.frag", "light_point.frag", "lighting_common.glsl",
                           "emissive.frag", "model.frag", "model.vert"}) {
    const auto found = embedded.find(std::string("shaders/") + file);
    ASSERT_NE(found, embedded.end()) << file;
    EXPECT_EQ(found->second, readFile(root + "/engine-patch/common/shaders/" + file)) << file;
  }
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root + "/shaders")) {
    if (!entry.is_regular_file()) continue;
    EXPECT_EQ(readFile(entry.path().string()).find("lighting_common"), std::string::npos) << entry.path();
  }
  // The engines' folders hold their C++ and their patch; every shader they compile is in common/shaders.
  for (const char* engine : {"/engine-patch/fso-host", "/engine-patch/second-host"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root + engine))
      for (const char* shader : {".frag", ".vert", ".glsl", ".comp"})
        EXPECT_NE(entry.path().extension(), shader) << entry.path();
}

TEST(Slices, TheHostsGBufferHoldsTheResolvedSurfaceAfterShade) {
  // Passes after lighting (SSAO, fog, debug views) read the host's G-buffer: after a slice method's
  // shade() it holds what `resolve` leaves there, bit for bit, unless the host opts out.
  PatchedHost host("default", 96, 72);
  const host::HostTargets& t = host.renderer->targets();
  auto gbuffer = [&] {
    std::vector<float> all;
    for (GLuint texture : {t.color, t.position, t.normal, t.specular, t.emissive}) {
      std::vector<float> pixels(size_t(t.width) * t.height * 4);
      glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
      all.insert(all.end(), pixels.begin(), pixels.end());
    }
    return all;
  };
  host.render("resolve");
  const std::vector<float> resolved = gbuffer();
  for (const char* method : {"edge", "adaptive", "aggregate", "per-sample", "smaa-s2x"}) {
    host.render(method);
    EXPECT_TRUE(gbuffer() == resolved) << method;  // bit for bit (NaN-free: the scene has none)
  }
  host.render("per-sample@restore_gbuffer_after_shade=off");
  EXPECT_FALSE(gbuffer() == resolved) << "opted out: the last slice's samples stay";
}

// What the host draws into its G-buffer between resolve() and shade() (a decal, a deferred blood splat) is
// what its lighting sees at single-count pixels and what the G-buffer holds after shade(): the restore
// copies back what the slices overwrote, rather than resolving the model pass again over it.
TEST(Slices, WhatTheHostWritesBetweenResolveAndShadeIsThereAfterShade) {
  constexpr int w = 8, h = 4;
  SyntheticFrame frame(w, h);
  std::vector<std::vector<SyntheticSample>> pixels(w * h, {surfaceSample(10)});
  pixels[0] = {surfaceSample(10), backgroundSample(), surfaceSample(10), backgroundSample()};  // an edge
  for (const retroaa::Method method : {retroaa::Method::Edge, retroaa::Method::PerSample}) {
    auto hooks = frame.attach(method);
    ASSERT_TRUE(hooks);
    retroaa::Plugin& plugin = hooks->plugin();
    fillGeometry(plugin, w, h, pixels);
    ASSERT_TRUE(plugin.resolve({1.0f}));
    const GLuint albedo = frame.renderer->targets().color;
    const float decal[4] = {0.25f, 0.75f, 0.125f, 1.0f};
    glClearTexImage(albedo, 0, GL_RGBA, GL_FLOAT, decal);
    ASSERT_TRUE(plugin.shade([&](GLuint target) { albedoAsLight(albedo, target, w, h); }));
    for (const glm::vec4& texel : frame.read(albedo))
      EXPECT_EQ(texel, glm::vec4(0.25f, 0.75f, 0.125f, 1.0f)) << retroaa::toString(method);
  }
}

TEST(Slices, BackgroundSamplesReachTheHostsLightingAsTheHostClearedThem) {
  // A lighting stand-in that outputs the normal it reads: a silhouette pixel's two background samples
  // (normal cleared to 0) must be lit with the host's own clear values, not with an invented normal,
  // and background pixels must see exactly what `off` shows them.
  constexpr int w = 8, h = 4;
  SyntheticFrame frame(w, h);
  std::vector<std::vector<SyntheticSample>> pixels(w * h, {backgroundSample()});
  pixels[0] = {surfaceSample(10), backgroundSample(), surfaceSample(10), backgroundSample()};
  auto hooks = frame.attach(retroaa::Method::PerSample);
  ASSERT_TRUE(hooks);
  retroaa::Plugin& plugin = hooks->plugin();
  fillGeometry(plugin, w, h, pixels);
  ASSERT_TRUE(plugin.resolve({1.0f}));
  const GLuint normal = frame.renderer->targets().normal;
  ASSERT_TRUE(plugin.shade([&](GLuint target) { albedoAsLight(normal, target, w, h); }));
  const std::vector<glm::vec4> light = frame.read(frame.renderer->targets().lightTexture);
  EXPECT_NEAR(light[0].z, 0.5f, 1e-3f) << "two samples facing the camera, two background samples with normal 0";
  for (size_t i = 1; i < light.size(); ++i) EXPECT_EQ(light[i].z, 0.0f) << "background pixel " << i;
}
