// Every method in the second host (engine-patch/second-host/second_renderer.h), a deferred renderer shaped
// unlike FreeSpace Open: no position target (depth buffer, reversed-Z D32F), octahedral world normals,
// lighting straight into an sRGB display, a forward pass after lighting. Each method must run without a
// GL error, leave the background as the host drew it, anti-alias silhouettes at least as well as `off`
// when it is a multi-sample method, and leave the host's G-buffer holding the resolved surface.
#include "commands.h"
#include "image_io.h"
#include "second_host_patch.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

using namespace testing_support;

namespace {

constexpr int kWidth = 192, kHeight = 144;

struct SecondHost {
  host::Scene scene = host::loadScene("default");
  std::unique_ptr<host::SecondRenderer> renderer;
  std::unique_ptr<patch::SecondHostHooks> hooks;

  explicit SecondHost(bool worldPositionTarget = false) {
    context();
    renderer = std::make_unique<host::SecondRenderer>(scene, kWidth, kHeight, worldPositionTarget);
    auto created = patch::SecondHostHooks::create(renderer->targets(), retroaa::Config{});
    if (!created) throw std::runtime_error(created.error().message);
    hooks = std::move(created.value());
    renderer->setSeams(hooks.get());
  }
  app::DisplayImage render(const std::string& spec) {
    const retroaa::Status status = hooks->plugin().reconfigure(app::parseMethodSpec(spec, {}).config);
    if (!status) throw std::runtime_error(status.error().message);
    renderer->renderFrame(scene.camera);
    return app::DisplayImage::fromRgba8(kWidth, kHeight, renderer->readDisplay());
  }
  // The host's G-buffer and depth as floats (GL rows): normal RG, albedo+specular RGBA, depth.
  std::vector<float> gbuffer() const {
    const host::SecondTargets& t = renderer->targets();
    std::vector<float> all, part(size_t(kWidth) * kHeight * 4);
    for (GLuint texture : {t.normal, t.albedoSpecular}) {
      glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(part.size() * 4), part.data());
      all.insert(all.end(), part.begin(), part.end());
    }
    std::vector<float> depth(size_t(kWidth) * kHeight);
    glGetTextureImage(t.depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * 4), depth.data());
    all.insert(all.end(), depth.begin(), depth.end());
    return all;
  }
  std::vector<float> depth() const {
    const std::vector<float> all = gbuffer();
    return {all.end() - kWidth * kHeight, all.end()};
  }
};

// Pixels (top-down, as DisplayImage) where no geometry is: the depth stays far at every position of an
// 8×8 grid over the pixel and over its eight neighbours (no filter's first ring reaches geometry).
std::vector<bool> openBackground(SecondHost& host) {
  std::vector<bool> empty(size_t(kWidth) * kHeight, true);
  host.hooks->plugin().reconfigure(app::parseMethodSpec("off", {}).config);
  for (int sy = 0; sy < 8; ++sy)
    for (int sx = 0; sx < 8; ++sx) {
      host.renderer->renderFrame(host.scene.camera, glm::vec2((sx + 0.5f) / 8 - 0.5f, (sy + 0.5f) / 8 - 0.5f));
      const std::vector<float> depth = host.depth();
      for (size_t i = 0; i < empty.size(); ++i) empty[i] = empty[i] && depth[i] <= 0.0f;
    }
  std::vector<bool> open(size_t(kWidth) * kHeight, false);
  for (int y = 1; y + 1 < kHeight; ++y)
    for (int x = 1; x + 1 < kWidth; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) all = all && empty[size_t(y + dy) * kWidth + x + dx];
      open[size_t(kHeight - 1 - y) * kWidth + x] = all;  // GL rows run bottom-up
    }
  return open;
}

// RETROAA_SECOND_HOST_IMAGES=folder keeps each method's image, to look at.
void writeImageIfAsked(const std::string& name, const std::vector<uint8_t>& rgba) {
  if (const char* folder = std::getenv("RETROAA_SECOND_HOST_IMAGES"))
    app::writeImage8(std::string(folder) + "/" + name + ".png", kWidth, kHeight, rgba, {});
}

ScoringTruth scoringTruth(SecondHost& host) {
  host.hooks->plugin().reconfigure(app::parseMethodSpec("off", {}).config);
  host.renderer->setStockPath(true);
  const host::GroundTruth truth = host::renderGroundTruth(*host.renderer, host.scene.camera, 4);
  host.renderer->setStockPath(false);
  return {app::DisplayImage::fromRgba8(truth.width, truth.height, truth.display),
          app::edgeMaskFromSpread(truth.lumaStdDev),
          {}};
}

size_t changedPixels(const app::DisplayImage& a, const app::DisplayImage& b, const std::vector<bool>& where) {
  size_t changed = 0;
  for (size_t i = 0; i < where.size(); ++i)
    if (where[i])
      for (int c = 0; c < 3; ++c) changed += a.rgb[i * 3 + c] != b.rgb[i * 3 + c];
  return changed;
}

void checkMethod(const std::string& spec) {
  SecondHost host;
  const std::vector<bool> open = openBackground(host);
  const int errorsBefore = context().debugErrorCount();
  const app::DisplayImage off = host.render("off");
  const std::vector<float> offGBuffer = host.gbuffer();
  const app::DisplayImage image = host.render(spec);
  const std::vector<float> gbuffer = host.gbuffer();
  writeImageIfAsked(spec, host.renderer->readDisplay());
  EXPECT_EQ(host.hooks->lastError(), "");
  EXPECT_EQ(context().debugErrorCount(), errorsBefore) << spec << " raised GL errors";
  for (const std::string& warning : host.hooks->plugin().warnings())  // a compute pass asked for runs here
    EXPECT_EQ(warning.find("using the full-screen pass"), std::string::npos) << warning;
  for (float value : gbuffer) ASSERT_TRUE(std::isfinite(value)) << spec << ": the host's G-buffer holds " << value;

  // The background is the host's own: no relit sky, no halo.
  EXPECT_GT(std::count(open.begin(), open.end(), true), kWidth * kHeight / 10) << "the scene should show open sky";
  EXPECT_EQ(changedPixels(image, off, open), 0u) << spec << " changed background pixels";

  const retroaa::Config granted = host.hooks->plugin().config();
  const retroaa::MethodInfo* method = retroaa::findMethod(granted.method);
  if (host.hooks->plugin().multisampledAttachment(retroaa::AttachmentRole::Albedo) != 0) {
    // The host's G-buffer after shade() is the resolved surface: what `resolve` leaves there (from the
    // same source: multisampled, or supersampled as `ssaa` makes it).
    host.render("resolve@supersample=" + std::to_string(granted.supersample));
    EXPECT_EQ(host.gbuffer(), gbuffer) << spec << " left the host's G-buffer unlike resolve's";
  } else {
    EXPECT_EQ(offGBuffer, gbuffer) << spec << " changed the host's G-buffer";
  }

  const ScoringTruth scoring = scoringTruth(host);
  const app::ErrorMetrics offError = scoring.score(off), methodError = scoring.score(image);
  std::printf("%s: edge PSNR %.2f dB (off %.2f dB), interior %.2f dB (off %.2f dB)\n", spec.c_str(),
              methodError.edgePsnrDb, offError.edgePsnrDb, methodError.interiorPsnrDb, offError.interiorPsnrDb);
  if ((method->multisampled && granted.samples > 1) || granted.method == retroaa::Method::Ssaa) {
    EXPECT_GE(methodError.edgePsnrDb, offError.edgePsnrDb) << spec << " anti-aliases worse than off";
  }
}

}  // namespace

// One test per method: the matrix below must name every method the plugin has.
#define SECOND_HOST_METHOD(Name, spec) \
  TEST(SecondHost, Name##KeepsTheBackgroundAndTheResolvedGBufferAndBeatsOffOnEdges) { checkMethod(spec); }
SECOND_HOST_METHOD(Off, "off")
SECOND_HOST_METHOD(Fxaa, "fxaa")
SECOND_HOST_METHOD(Resolve, "resolve")
SECOND_HOST_METHOD(ResolveCompute, "resolve@resolve_compute=on")
SECOND_HOST_METHOD(Edge, "edge")
SECOND_HOST_METHOD(EdgeResolveCompute, "edge@resolve_compute=on")
SECOND_HOST_METHOD(PerSample, "per-sample")
SECOND_HOST_METHOD(Adaptive, "adaptive")
SECOND_HOST_METHOD(Aggregate, "aggregate")
SECOND_HOST_METHOD(Coverage, "coverage")
SECOND_HOST_METHOD(Reconstruct, "reconstruct")
SECOND_HOST_METHOD(ReconstructCompute, "reconstruct@reconstruct_compute=on")
SECOND_HOST_METHOD(Smaa, "smaa")
SECOND_HOST_METHOD(SmaaS2x, "smaa-s2x")
SECOND_HOST_METHOD(Ssaa, "ssaa")
// `temporal` has its own second-host test (temporal_tests.cpp, TheSecondHostJitters…): its jittered
// frames move the background too, which checkMethod holds still.
const std::set<std::string> kMatrix = {"off",      "fxaa",      "resolve",  "edge",        "per-sample",
                                       "adaptive", "aggregate", "coverage", "reconstruct", "smaa",
                                       "smaa-s2x", "ssaa",      "temporal"};

TEST(SecondHost, AnEvenSplitIsDecidedByTheNeighbourhoodWhereTheLayoutLightsIntoItsDisplay) {
  // This host lights straight into its sRGB display: resolve_even_split=auto asks the 3x3 neighbourhood,
  // which is at least as good on edges as the nearer middle against its display-averaged ground truth.
  SecondHost host;
  const app::DisplayImage automatic = host.render("resolve");
  const app::DisplayImage neighbours = host.render("resolve@resolve_even_split=neighbours");
  const app::DisplayImage nearer = host.render("resolve@resolve_even_split=nearer");
  EXPECT_EQ(automatic.rgb, neighbours.rgb);
  EXPECT_NE(neighbours.rgb, nearer.rgb) << "the scene has pixels split 2 of 4";
  const ScoringTruth scoring = scoringTruth(host);
  EXPECT_GE(scoring.score(neighbours).edgePsnrDb, scoring.score(nearer).edgePsnrDb);
}

TEST(SecondHost, TheMatrixNamesEveryMethod) {
  for (const retroaa::MethodInfo& row : retroaa::methodTable())
    EXPECT_TRUE(kMatrix.count(row.name)) << row.name << " has no SecondHost test";
}

TEST(SecondHost, ReconstructOnWorldSpaceNormalsBeatsFxaaOnEdgesByADecibel) {
  // This host's normals are world-space (octahedral): reconstruct's normal tests must hold in any space.
  SecondHost host;
  const ScoringTruth truth = scoringTruth(host);
  const double fxaa = truth.score(host.render("fxaa")).edgePsnrDb;
  const double reconstruct = truth.score(host.render("reconstruct")).edgePsnrDb;
  EXPECT_GE(reconstruct, fxaa + 1.0) << "fxaa " << fxaa;
}

TEST(SecondHost, BenchTakesTheSecondHostAndRefusesAnUnknownOne) {
  const auto [r, document] = runBench(
      "--host second --methods off,per-sample --width 96 --height 72 --gt-samples 3 --repeats 1 --wall-frames 0");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(document["rows"].size(), 2u);
  EXPECT_GT(document["rows"][1]["edge_psnr_db"].get<double>(), document["rows"][0]["edge_psnr_db"].get<double>());
  EXPECT_DOUBLE_EQ(document["rows"][1]["evals_per_pixel"].get<double>(), 4.0);

  const CliRun unknown = runBench("--host unreal --methods off --width 32 --height 24").run;
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("--host"), std::string::npos) << unknown.output;
}

namespace {
// The second host described by a layout other than its patch's (`layout`), through seams of the test's
// own: the plugin gets the frame's view matrix unless `passViewMatrix` is false.
struct LayoutSeams : host::SecondSeams {
  std::unique_ptr<retroaa::Plugin> plugin;
  bool passViewMatrix = true;
  GLuint geometryTarget(GLuint) override { return plugin->geometryFramebuffer(); }
  void geometryDone(const host::FrameView& view) override {
    retroaa::FrameInfo frame{view.verticalFovRadians, view.nearPlane, view.farPlane};
    if (passViewMatrix) std::copy_n(&view.view[0][0], 16, frame.viewMatrix);
    EXPECT_TRUE(plugin->resolve(frame));
  }
  void lighting(const std::function<void(GLuint)>& pass, GLuint) override { EXPECT_TRUE(plugin->shade(pass)); }
  void frameDone() override { EXPECT_TRUE(plugin->post()); }
};

// The host keeping world positions in a third attachment its lighting never reads, described with
// DepthSource::WorldPosition: the plugin takes view depth from them and the frame's view matrix.
retroaa::GBufferLayout worldPositionLayout(const host::SecondTargets& t) {
  retroaa::GBufferLayout layout = patch::describeSecondHost(t);
  layout.attachments.push_back({retroaa::AttachmentRole::ViewPosition, GL_RGBA32F, t.worldPosition});
  layout.depthSource = retroaa::DepthSource::WorldPosition;
  layout.lightingReadsDepth = true;  // the host's lighting still rebuilds positions from depth
  return layout;
}

// Three frames of `spec` in `host` under `layout` (the layout check reads back a frame later); the
// display and the plugin's warnings.
std::pair<app::DisplayImage, std::vector<std::string>> renderWithLayout(SecondHost& host, const std::string& spec,
                                                                        const retroaa::GBufferLayout& layout,
                                                                        bool passViewMatrix = true) {
  LayoutSeams seams;
  seams.passViewMatrix = passViewMatrix;
  retroaa::Description description;
  description.config = app::parseMethodSpec(spec, {}).config;
  description.layout = layout;
  auto created = retroaa::Plugin::create(description);
  if (!created) throw std::runtime_error(created.error().message);
  seams.plugin = std::move(created.value());
  host.renderer->setSeams(&seams);
  for (int frame = 0; frame < 3; ++frame) host.renderer->renderFrame(host.scene.camera);
  host.renderer->setSeams(host.hooks.get());
  return {app::DisplayImage::fromRgba8(kWidth, kHeight, host.renderer->readDisplay()), seams.plugin->warnings()};
}
}  // namespace

TEST(SecondHost, WorldPositionsAsTheDepthSourceAntiAliasLikeTheDepthBuffer) {
  SecondHost host(true);
  const std::vector<bool> open = openBackground(host);
  const ScoringTruth scoring = scoringTruth(host);
  const app::DisplayImage off = host.render("off");
  const double offEdge = scoring.score(off).edgePsnrDb;
  const int errorsBefore = context().debugErrorCount();
  for (const std::string spec : {"resolve", "edge", "aggregate", "adaptive"}) {
    const double fromDepth = scoring.score(host.render(spec)).edgePsnrDb;
    const auto [image, warnings] = renderWithLayout(host, spec, worldPositionLayout(host.renderer->targets()));
    const double fromWorld = scoring.score(image).edgePsnrDb;
    std::printf("%s: edge PSNR %.2f dB from world positions, %.2f dB from depth (off %.2f dB)\n", spec.c_str(),
                fromWorld, fromDepth, offEdge);
    EXPECT_GE(fromWorld, offEdge) << spec;
    EXPECT_NEAR(fromWorld, fromDepth, 0.25) << spec;
    EXPECT_EQ(changedPixels(image, off, open), 0u) << spec << " changed background pixels";
    for (const std::string& warning : warnings) ADD_FAILURE() << spec << ": " << warning;
  }
  EXPECT_EQ(context().debugErrorCount(), errorsBefore);
}

TEST(SecondHost, WorldPositionsWithoutTheViewMatrixAreNamedInAWarning) {
  SecondHost host(true);
  const auto [image, warnings] = renderWithLayout(host, "edge", worldPositionLayout(host.renderer->targets()), false);
  std::string all;
  for (const std::string& warning : warnings) all += warning + "\n";
  EXPECT_NE(all.find("FrameInfo::viewMatrix"), std::string::npos) << all;
}

TEST(SecondHost, WithoutALightTextureTheSlicesDrawIntoTheLightFramebuffer) {
  // A host that names only the framebuffer it lights into (the window's, say): the slices sum in the
  // plugin's half-float target and draw it there once, as they do for this host's 8-bit sRGB display.
  SecondHost host;
  const int errorsBefore = context().debugErrorCount();
  for (const std::string spec : {"edge", "aggregate", "smaa-s2x"}) {
    const app::DisplayImage withTexture = host.render(spec);
    retroaa::GBufferLayout layout = patch::describeSecondHost(host.renderer->targets());
    layout.lightTexture = 0;
    const app::DisplayImage withoutTexture = renderWithLayout(host, spec, layout).first;
    EXPECT_EQ(withoutTexture.rgb, withTexture.rgb) << spec;
  }
  EXPECT_EQ(context().debugErrorCount(), errorsBefore);
}
