// The whole frame: a host whose shade() callback composes scene colour after lighting (a material combine,
// a sky at the far plane), cut-out geometry shaded per sample, and the display's encoding. Hand-written
// samples on the FSO-shaped host's targets; the composed target is the test's own, as a host keeps one.
#include "test_support.h"

#include <epoxy/gl.h>

#include <glm/glm.hpp>

#include <cmath>
#include <functional>

namespace {

using namespace testing_support;

constexpr int kWidth = 8, kHeight = 4;
const glm::vec3 kSky(0.1f, 0.2f, 0.9f);

// A composed target as SuperTuxKart's FBO_COLORS: its own RGBA16F colour over the host's depth-stencil.
struct ComposedTarget {
  GLuint texture = 0, framebuffer = 0;
  explicit ComposedTarget(GLuint hostDepthStencil) {
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_RGBA16F, kWidth, kHeight);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_STENCIL_ATTACHMENT, hostDepthStencil, 0);
  }
  ~ComposedTarget() {
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
  }
};

// The host's stage after the G-buffer, as a combining engine has it: lighting writes irradiance alone (the
// specular attachment's red channel stands for it), a combine multiplies it by the albedo, and a sky is
// added where the depth test at the far plane passes (GL_LEQUAL against depth 1).
void composeFrame(const retroaa::ShadeTargets& targets, const host::HostTargets& host) {
  glBindFramebuffer(GL_FRAMEBUFFER, targets.light);
  glViewport(0, 0, kWidth, kHeight);
  glBindTextureUnit(0, host.specular);
  drawWithFragment(R"(#version 450 core
layout(binding = 0) uniform sampler2D uSpecular;
out vec4 outLight;
void main() { outLight = vec4(vec3(texelFetch(uSpecular, ivec2(gl_FragCoord.xy), 0).r), 1.0); })",
                   [](GLuint) {});
  glBindFramebuffer(GL_FRAMEBUFFER, targets.composed);
  glBindTextureUnit(0, host.lightTexture);
  glBindTextureUnit(1, host.color);
  drawWithFragment(R"(#version 450 core
layout(binding = 0) uniform sampler2D uLight;
layout(binding = 1) uniform sampler2D uAlbedo;
out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  outColor = vec4(texelFetch(uLight, p, 0).rgb * texelFetch(uAlbedo, p, 0).rgb, 1.0);
})",
                   [](GLuint) {});
  // The sky: a full-screen triangle at the far plane, drawn where nothing nearer is.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glDepthRange(1.0, 1.0);
  drawWithFragment(
      R"(#version 450 core
uniform vec3 uSky;
out vec4 outColor;
void main() { outColor = vec4(uSky, 0.0); })",
      [](GLuint program) { glProgramUniform3f(program, glGetUniformLocation(program, "uSky"), 0.1f, 0.2f, 0.9f); });
  glDepthRange(0.0, 1.0);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
}

SyntheticSample litSurface(glm::vec3 albedo, float irradiance, float depth = 2.0f) {
  SyntheticSample sample = surfaceSample(depth, {0, 0, 1}, albedo);
  sample.attachments[3] = glm::vec4(irradiance, 0, 0, 1);
  return sample;
}

// Pixel 1: half red surface lit at 1, half sky. Pixel 2: red lit at 1 beside a green surface behind it lit
// at 0.2 (no sky). Pixel 0 and the rest: a grey surface lit at 0.5, one sample for all.
std::vector<std::vector<SyntheticSample>> composedScene() {
  std::vector<std::vector<SyntheticSample>> pixels(size_t(kWidth) * kHeight, {litSurface(glm::vec3(0.5f), 0.5f)});
  const SyntheticSample red = litSurface({1, 0, 0}, 1.0f), green = litSurface({0, 1, 0}, 0.2f, 3.0f);
  pixels[1] = {red, red, backgroundSample(), backgroundSample()};
  pixels[2] = {red, red, green, green};
  return pixels;
}

struct ComposedRun {
  std::vector<glm::vec4> composed;
  retroaa::Stats stats;
};

// A host's forward pass: draws between beginForward() and endForward() into the framebuffer it returned.
using ForwardPass = std::function<void()>;

// `afterShade`: what the host draws into its scene colour between shade() and beginForward() (a glow).
ComposedRun runComposed(const std::string& spec, const ForwardPass& forward = nullptr,
                        const ForwardPass& afterShade = nullptr) {
  SyntheticFrame frame(kWidth, kHeight);
  const host::HostTargets& host = frame.renderer->targets();
  ComposedTarget target(host.depthStencil);
  retroaa::Description description;
  EXPECT_TRUE(retroaa::applyMethodSpec(description.config, spec));
  description.config.samples = 4;
  description.layout = patch::describeHostGBuffer(host);
  description.layout.composedFramebuffer = target.framebuffer;
  description.layout.composedTexture = target.texture;
  description.layout.drawsForwardPasses = forward != nullptr;
  auto created = retroaa::Plugin::create(description);
  EXPECT_TRUE(created) << (created ? "" : created.error().message);
  if (!created) return {};
  retroaa::Plugin& plugin = *created.value();
  fillGeometry(plugin, kWidth, kHeight, composedScene());
  EXPECT_TRUE(plugin.resolve({1.0f}));
  const float black[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(target.framebuffer, GL_COLOR, 0, black);
  glDisable(GL_MULTISAMPLE);  // as Irrlicht leaves it on a window without MSAA: the plugin's passes must not care
  EXPECT_TRUE(plugin.shade([&](const retroaa::ShadeTargets& targets) { composeFrame(targets, host); }));
  glEnable(GL_MULTISAMPLE);
  if (afterShade) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(0, 0, kWidth, kHeight);
    afterShade();
  }
  if (forward) {
    const retroaa::Result<retroaa::GLuintHandle> framebuffer = plugin.beginForward();
    EXPECT_TRUE(framebuffer) << (framebuffer ? "" : framebuffer.error().message);
    if (framebuffer) {
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.value());
      glViewport(0, 0, kWidth, kHeight);
      glEnable(GL_MULTISAMPLE);
      forward();
    }
    EXPECT_TRUE(plugin.endForward());
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(plugin.warnings().empty());
  return {frame.read(target.texture), plugin.waitForStats()};
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << what << " channel " << c;
}

TEST(WholeFrame, PerSampleComposesEachSampleWithItsOwnMaterialAndSky) {
  const ComposedRun run = runComposed("per-sample");
  ASSERT_EQ(run.composed.size(), size_t(kWidth) * kHeight);
  // avg(light × albedo) + the sky's share, not avg(light) × avg(albedo) or a sky of all or nothing.
  expectNear(run.composed[1], 0.5f * glm::vec3(1, 0, 0) + 0.5f * kSky, 0.01f, "red beside sky");
  expectNear(run.composed[2], 0.5f * glm::vec3(1, 0, 0) + 0.5f * glm::vec3(0, 0.2f, 0), 0.01f, "red beside green");
  expectNear(run.composed[0], glm::vec3(0.25f), 0.01f, "grey surface");
  EXPECT_NEAR(run.stats.evaluationsPerPixel(), 4.0, 1e-9);
}

TEST(WholeFrame, EdgeComposesOnlyItsEdgePixelsPerSample) {
  const ComposedRun run = runComposed("edge");
  ASSERT_EQ(run.composed.size(), size_t(kWidth) * kHeight);
  expectNear(run.composed[1], 0.5f * glm::vec3(1, 0, 0) + 0.5f * kSky, 0.01f, "red beside sky");
  expectNear(run.composed[2], glm::vec3(0.5f, 0.1f, 0), 0.01f, "red beside green");
  expectNear(run.composed[5], glm::vec3(0.25f), 0.01f, "grey surface");
  EXPECT_LT(run.stats.evaluationsPerPixel(), 2.0);  // two edge pixels of 32 lit 4 times
}

// A composing host's slices keep each slice's depth in the mask (its combine may depth-test against it): the
// G-buffer write writes it too, one draw a slice over the slice's pixels, not a second depth write after it.
TEST(WholeFrame, EachSliceWritesItsGBufferAndItsKeptDepthInOneDraw) {
  const ComposedRun run = runComposed("per-sample@measure_gpu_time=on");
  expectNear(run.composed[1], 0.5f * glm::vec3(1, 0, 0) + 0.5f * kSky, 0.01f, "red beside sky");
  uint64_t writeFragments = 0, resolveFragments = 0;
  for (const retroaa::PassStats& pass : run.stats.passes) {
    if (pass.name == "slices.write") writeFragments += pass.fragmentInvocations;  // an entry a slice
    if (pass.name == "resolve") resolveFragments = pass.fragmentInvocations;      // one full-screen draw
  }
  ASSERT_GT(resolveFragments, 0u) << "no pipeline statistics";
  EXPECT_EQ(writeFragments, 4 * resolveFragments);  // four slices, each writing every pixel once
}

TEST(WholeFrame, ASingleSliceMethodComposesIntoTheHostsTargetOnce) {
  const ComposedRun run = runComposed("resolve");
  ASSERT_EQ(run.composed.size(), size_t(kWidth) * kHeight);
  expectNear(run.composed[0], glm::vec3(0.25f), 0.01f, "grey surface");
  // One surface per pixel: the sky is all there or not at all.
  const glm::vec3 skyEdge = run.composed[1];
  EXPECT_TRUE(glm::all(glm::lessThan(glm::abs(skyEdge - glm::vec3(1, 0, 0)), glm::vec3(0.01f))) ||
              glm::all(glm::lessThan(glm::abs(skyEdge - kSky), glm::vec3(0.01f))))
      << skyEdge.x << " " << skyEdge.y << " " << skyEdge.z;
}

TEST(WholeFrame, AComposingLayoutRefusesALightingCallbackAndAHalfNamedTarget) {
  SyntheticFrame frame(kWidth, kHeight);
  const host::HostTargets& host = frame.renderer->targets();
  ComposedTarget target(host.depthStencil);
  retroaa::Description description;
  description.config.method = retroaa::Method::PerSample;
  description.layout = patch::describeHostGBuffer(host);
  description.layout.composedFramebuffer = target.framebuffer;
  auto halfNamed = retroaa::Plugin::create(description);
  ASSERT_FALSE(halfNamed);
  EXPECT_EQ(halfNamed.error().code, retroaa::ErrorCode::InvalidLayout);
  EXPECT_NE(halfNamed.error().message.find("composedTexture"), std::string::npos) << halfNamed.error().message;

  description.layout.composedTexture = target.texture;
  auto created = retroaa::Plugin::create(description);
  ASSERT_TRUE(created) << created.error().message;
  fillGeometry(*created.value(), kWidth, kHeight, composedScene());
  ASSERT_TRUE(created.value()->resolve({1.0f}));
  const retroaa::Status lightOnly = created.value()->shade([](retroaa::GLuintHandle) {});
  ASSERT_FALSE(lightOnly);
  EXPECT_EQ(lightOnly.error().code, retroaa::ErrorCode::InvalidLayout);
  EXPECT_NE(lightOnly.error().message.find("ComposingFunction"), std::string::npos) << lightOnly.error().message;
}

// A forward pass's triangle in pixel coordinates, one colour, depth-tested (GL_LESS) at window depth `depth`.
void drawForwardTriangle(const glm::vec2 (&corners)[3], float depth, glm::vec3 colour,
                         glm::vec2 size = {kWidth, kHeight}) {
  const char* vertexSource = R"(#version 450 core
out gl_PerVertex { vec4 gl_Position; };
uniform vec2 uCorners[3];
uniform vec2 uSize;
uniform float uDepth;
void main() { gl_Position = vec4(uCorners[gl_VertexID] / uSize * 2.0 - 1.0, uDepth * 2.0 - 1.0, 1.0); })";
  const char* fragmentSource = R"(#version 450 core
uniform vec3 uColour;
out vec4 outColour;
void main() { outColour = vec4(uColour, 1.0); })";
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  drawTriangleWith(vertexSource, fragmentSource, [&](GLuint vertex, GLuint fragment) {
    glProgramUniform2fv(vertex, glGetUniformLocation(vertex, "uCorners"), 3, &corners[0].x);
    glProgramUniform2f(vertex, glGetUniformLocation(vertex, "uSize"), size.x, size.y);
    glProgramUniform1f(vertex, glGetUniformLocation(vertex, "uDepth"), depth);
    glProgramUniform3f(fragment, glGetUniformLocation(fragment, "uColour"), colour.r, colour.g, colour.b);
  });
  glDisable(GL_DEPTH_TEST);
}

const glm::vec3 kForward(0, 0, 1);

// How many pixels hold the forward colour in part, strictly between none and all of it: over the grey surface
// a share t of blue makes blue exceed red by t.
int partlyForward(const std::vector<glm::vec4>& composed) {
  int partial = 0;
  for (const glm::vec4& pixel : composed) partial += pixel.b - pixel.r > 0.05f && pixel.b - pixel.r < 0.95f;
  return partial;
}

TEST(WholeFrame, ForwardGeometryIsAntiAliasedByTheGBuffersSamples) {
  // In front of everything, its edge x = 3.5 + 0.25 y (pixels) crossing one grey pixel of each row.
  const ForwardPass edge = [] { drawForwardTriangle({{1, -10}, {11, 30}, {-50, 10}}, 0.0f, kForward); };
  for (const char* spec : {"per-sample", "edge", "resolve", "adaptive", "aggregate", "smaa-s2x"}) {
    const ComposedRun run = runComposed(spec, edge);
    ASSERT_EQ(run.composed.size(), size_t(kWidth) * kHeight) << spec;
    EXPECT_GE(partlyForward(run.composed), kHeight) << spec;
    expectNear(run.composed[0], kForward, 0.01f, std::string(spec) + ": covered");
    expectNear(run.composed[kWidth - 1], glm::vec3(0.25f), 0.01f, std::string(spec) + ": untouched");
  }
  const ComposedRun off = runComposed("off", edge);
  ASSERT_EQ(off.composed.size(), size_t(kWidth) * kHeight);
  EXPECT_EQ(partlyForward(off.composed), 0);  // one sample a pixel: all or nothing
}

TEST(WholeFrame, ForwardGeometryBehindASilhouetteIsDepthTestedPerSample) {
  // Behind the surfaces (window depth 0.6; a surface at 2 m is 0.18 in the host's logarithmic depth), in
  // front of the sky: it replaces the sky's samples of pixel 1 and nothing of pixel 2.
  const ForwardPass behind = [] { drawForwardTriangle({{-10, -10}, {30, -10}, {-10, 30}}, 0.6f, kForward); };
  const ComposedRun run = runComposed("per-sample", behind);
  ASSERT_EQ(run.composed.size(), size_t(kWidth) * kHeight);
  expectNear(run.composed[1], 0.5f * glm::vec3(1, 0, 0) + 0.5f * kForward, 0.01f, "red beside a forward sky");
  expectNear(run.composed[2], glm::vec3(0.5f, 0.1f, 0), 0.01f, "red beside green");
}

TEST(WholeFrame, WhatTheHostDrawsBeforeItsForwardPassesReachesEverySample) {
  // A glow composited over the lit image after shade() (SuperTuxKart's: its halo vanished wherever the
  // slices had kept their samples for the forward passes, every pixel under per-sample).
  const ForwardPass glow = [] {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    drawForwardTriangle({{-10, -10}, {30, -10}, {-10, 30}}, 0.0f, {0, 0.2f, 0});
    glDisable(GL_BLEND);
  };
  const ForwardPass nothing = [] {};
  for (const char* spec : {"per-sample", "edge", "aggregate", "resolve"}) {
    const ComposedRun plain = runComposed(spec, nothing), glowing = runComposed(spec, nothing, glow);
    ASSERT_EQ(plain.composed.size(), size_t(kWidth) * kHeight) << spec;
    ASSERT_EQ(glowing.composed.size(), plain.composed.size()) << spec;
    for (size_t i = 0; i < plain.composed.size(); ++i)
      expectNear(glowing.composed[i], glm::vec3(plain.composed[i]) + glm::vec3(0, 0.2f, 0), 0.01f,
                 std::string(spec) + ": pixel " + std::to_string(i));
  }
}

TEST(WholeFrame, ForwardCallsOutOfOrderAreRefused) {
  SyntheticFrame frame(kWidth, kHeight);
  auto hooks = frame.attach(retroaa::Method::PerSample);
  ASSERT_TRUE(hooks);
  retroaa::Plugin& plugin = hooks->plugin();
  fillGeometry(plugin, kWidth, kHeight, {});
  ASSERT_TRUE(plugin.resolve({1.0f}));
  const auto early = plugin.beginForward();
  ASSERT_FALSE(early);
  EXPECT_EQ(early.error().code, retroaa::ErrorCode::WrongCallOrder);
  const retroaa::Status unopened = plugin.endForward();
  ASSERT_FALSE(unopened);
  EXPECT_EQ(unopened.error().code, retroaa::ErrorCode::WrongCallOrder);
  const GLuint color = frame.renderer->targets().color;
  ASSERT_TRUE(plugin.shade([&](GLuint target) { albedoAsLight(color, target, kWidth, kHeight); }));
  ASSERT_TRUE(plugin.beginForward());
  EXPECT_FALSE(plugin.beginForward());
  EXPECT_TRUE(plugin.endForward());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A cut-out drawn by a model shader that discards: the edge x = 3.5 + 0.25 y crosses pixels at a quarter of
// their width. Per-pixel shading decides each pixel at its centre; per-sample shading each sample. Its red
// channel is a texture that varies within a pixel; green and blue are 1. `counts` gets the slice counts.
std::vector<glm::vec4> cutOutLight(float sampleShading, retroaa::Method method = retroaa::Method::PerSample,
                                   std::vector<uint8_t>* counts = nullptr) {
  SyntheticFrame frame(kWidth, kHeight);
  retroaa::Config config;
  config.method = method;
  config.samples = 4;
  config.sampleShading = sampleShading;
  auto hooks = frame.attach(config);
  if (!hooks) return {};
  retroaa::Plugin& plugin = hooks->plugin();
  EXPECT_FLOAT_EQ(plugin.sampleShading(), sampleShading);
  fillGeometry(plugin, kWidth, kHeight, {});  // every sample background
  glBindFramebuffer(GL_FRAMEBUFFER, plugin.geometryFramebuffer());
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_MULTISAMPLE);
  glDisable(GL_DEPTH_TEST);
  if (plugin.sampleShading() > 0) {
    glEnable(GL_SAMPLE_SHADING);
    glMinSampleShading(plugin.sampleShading());
  }
  // The model shader: a white surface at depth 2 m whose "alpha texture" cuts it off past the edge. The
  // varying is what a texture coordinate would be: interpolated where the fragment shader runs.
  const std::string body = R"(
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outPosition;
layout(location = 2) out vec4 outNormal;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmissive;
in vec2 vScreen;
void main() {
  if (vScreen.x > 3.5 + 0.25 * vScreen.y) discard;
  outAlbedo = vec4(0.5 + 0.4 * sin(2.0 * vScreen.x + vScreen.y), 1.0, 1.0, 1.0);
  outPosition = vec4(0.0, 0.0, 2.0, 1.0); outNormal = vec4(0.0, 0.0, 1.0, 0.5);
  outSpecular = vec4(0.0); outEmissive = vec4(0.0, 0.0, 0.0, 1.0);
  gl_FragDepth = 0.5;
})";
  const std::string vertex = R"(#version 450 core
out gl_PerVertex { vec4 gl_Position; };
out vec2 vScreen;
uniform vec2 uSize;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
  vScreen = (p * 0.5 + 0.5) * uSize;
  gl_Position = vec4(p, 0.0, 1.0);
})";
  const std::string fragment = "#version 450 core\n" + body;
  drawTriangleWith(vertex.c_str(), fragment.c_str(), [](GLuint vertexProgram, GLuint) {
    glProgramUniform2f(vertexProgram, glGetUniformLocation(vertexProgram, "uSize"), float(kWidth), float(kHeight));
  });
  glDisable(GL_SAMPLE_SHADING);
  EXPECT_TRUE(plugin.resolve({1.0f}));
  const GLuint color = frame.renderer->targets().color;
  EXPECT_TRUE(plugin.shade([&](GLuint target) { albedoAsLight(color, target, kWidth, kHeight); }));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  if (counts) *counts = plugin.readSliceCounts();
  return frame.read(frame.renderer->targets().lightTexture);
}

// How many pixels of the edge's column hold a value strictly between the cut-out and the background.
int partialPixels(const std::vector<glm::vec4>& light) {
  int partial = 0;
  for (const glm::vec4& pixel : light) partial += pixel.g > 0.05f && pixel.g < 0.95f;
  return partial;
}

TEST(WholeFrame, SampleShadingAntiAliasesCutOutEdges) {
  const std::vector<glm::vec4> perPixel = cutOutLight(0.0f), perSample = cutOutLight(1.0f);
  ASSERT_EQ(perPixel.size(), size_t(kWidth) * kHeight);
  ASSERT_EQ(perSample.size(), perPixel.size());
  EXPECT_EQ(partialPixels(perPixel), 0);         // the discard decided each pixel whole
  EXPECT_GE(partialPixels(perSample), kHeight);  // each row's edge pixel is partly covered
  // Away from the edge both agree: covered on the left, background on the right.
  EXPECT_NEAR(perSample[0].g, 1.0f, 1e-3f);
  EXPECT_NEAR(perSample[kWidth - 1].g, perPixel[kWidth - 1].g, 1e-3f);
}

// Shaded per sample, one surface's samples differ bit for bit; `edge`'s default detector must still light
// only the pixels its discard cuts, not every pixel its texture varies in.
TEST(WholeFrame, EdgeLightsACutOutsEdgeNotItsTextureShadedPerSample) {
  std::vector<uint8_t> counts;
  const std::vector<glm::vec4> edge = cutOutLight(1.0f, retroaa::Method::Edge, &counts);
  const std::vector<glm::vec4> perSample = cutOutLight(1.0f);
  ASSERT_EQ(counts.size(), size_t(kWidth) * kHeight);
  ASSERT_EQ(edge.size(), perSample.size());
  int edgePixels = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool marked = counts[size_t(y) * kWidth + x] > 1;
      edgePixels += marked;
      // The discard's edge x = 3.5 + 0.25 (y + 0.5) lies in column 3 or 4; the cut-out's textured inside
      // (columns 0-2) and the background (5-7) are one surface each.
      if (x <= 2 || x >= 5) {
        EXPECT_FALSE(marked) << x << "," << y;
      }
    }
  EXPECT_GE(edgePixels, kHeight);
  // Unmarked pixels light their averaged albedo once; this light is linear in it, so they match.
  for (size_t i = 0; i < edge.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(edge[i][c], perSample[i][c], 2.0f / 255) << i;
}

TEST(WholeFrame, SampleShadingIsZeroWhereNothingDrawsMultisampled) {
  SyntheticFrame frame(kWidth, kHeight);
  retroaa::Config config;
  config.method = retroaa::Method::Fxaa;
  config.sampleShading = 1.0f;
  auto hooks = frame.attach(config);
  ASSERT_TRUE(hooks);
  EXPECT_EQ(hooks->plugin().sampleShading(), 0.0f);
  EXPECT_EQ(hooks->plugin().textureLodBias(), 0.0f);
}

TEST(WholeFrame, SampleShadingSharpensTheMipsByTheSamplesShaded) {
  // Each pixel averages the reads of the samples shaded, all at the pixel's mip: the mip of a render at √k
  // times the size is log2(√k) finer.
  SyntheticFrame frame(kWidth, kHeight);
  auto hooks = frame.attach(retroaa::Method::PerSample);
  ASSERT_TRUE(hooks);
  retroaa::Plugin& plugin = hooks->plugin();
  const std::pair<const char*, float> cases[] = {{"per-sample", 0.0f},
                                                 {"per-sample@sample_shading=1", -1.0f},
                                                 {"per-sample@sample_shading=0.5", -0.5f},
                                                 {"per-sample@sample_shading=0.25", 0.0f},  // one sample shaded
                                                 {"temporal@temporal_lod_bias=-0.5", -0.5f},
                                                 {"edge+temporal@sample_shading=1@temporal_lod_bias=-0.5", -1.0f},
                                                 {"edge+temporal@sample_shading=0.5@temporal_lod_bias=-2", -2.0f}};
  for (const auto& [spec, bias] : cases) {
    retroaa::Config config;
    ASSERT_TRUE(retroaa::applyMethodSpec(config, spec));
    ASSERT_TRUE(plugin.reconfigure(config));
    EXPECT_FLOAT_EQ(plugin.textureLodBias(), bias) << spec;
  }
}

TEST(WholeFrame, CutOutDrawsAreShadedPerSampleByDefaultAndTheRestAsAsked) {
  // A host that tells its cut-out draws apart shades them per sample where the method draws multisampled (the
  // default cutout_sample_shading=1), with the mip bias that goes with it; its other draws keep
  // sample_shading's; nothing draws multisampled under fxaa.
  SyntheticFrame frame(kWidth, kHeight);
  auto hooks = frame.attach(retroaa::Method::PerSample);
  ASSERT_TRUE(hooks);
  retroaa::Plugin& plugin = hooks->plugin();
  struct Case {
    const char* spec;
    float cutOutShading, cutOutBias, otherShading;
  };
  const Case cases[] = {{"per-sample", 1.0f, -1.0f, 0.0f},
                        {"edge", 1.0f, -1.0f, 0.0f},
                        {"per-sample@cutout_sample_shading=0", 0.0f, 0.0f, 0.0f},
                        {"per-sample@cutout_sample_shading=0.5", 0.5f, -0.5f, 0.0f},
                        {"per-sample@cutout_sample_shading=0@sample_shading=1", 1.0f, -1.0f, 1.0f},
                        {"reconstruct", 1.0f, -1.0f, 0.0f},  // its prepass draws multisampled
                        {"temporal@temporal_lod_bias=-0.5", 0.0f, -0.5f, 0.0f},
                        {"fxaa", 0.0f, 0.0f, 0.0f}};
  for (const Case& c : cases) {
    retroaa::Config config;
    ASSERT_TRUE(retroaa::applyMethodSpec(config, c.spec));
    ASSERT_TRUE(plugin.reconfigure(config));
    const retroaa::DrawSettings cutOut = plugin.cutOutDrawSettings();
    EXPECT_FLOAT_EQ(cutOut.sampleShading, c.cutOutShading) << c.spec;
    EXPECT_FLOAT_EQ(cutOut.textureLodBias, c.cutOutBias) << c.spec;
    EXPECT_FLOAT_EQ(plugin.sampleShading(), c.otherShading) << c.spec;
  }
}

}  // namespace

// The post filters that rebuild a pixel from its neighbours' colours know the opaque surfaces' depth alone.
// Left of x = 7.6 a surface (display 200, depth 0.5), right of it the background (display 30); a forward
// pass (a particle) draws blue over the background at column 8, rows 2 to 5, beside the silhouette.
constexpr int kFilterWidth = 16, kFilterHeight = 8;
bool drawnByTheForwardPass(int x, int y) { return x == 8 && y >= 2 && y <= 5; }

// The display after post(); `drawsForwardPasses`: what the layout says (the pass is drawn either way);
// `film`: the forward pass is a white film of a tenth's opacity over the whole frame instead of the particle.
std::vector<uint8_t> filteredBesideAForwardPass(const char* spec, bool drawsForwardPasses, bool film = false) {
  SyntheticFrame frame(kFilterWidth, kFilterHeight);
  const host::HostTargets& t = frame.renderer->targets();
  retroaa::Description description;
  EXPECT_TRUE(retroaa::applyMethodSpec(description.config, spec));
  description.config.samples = 4;
  description.layout = patch::describeHostGBuffer(t);
  description.layout.drawsForwardPasses = drawsForwardPasses;
  auto created = retroaa::Plugin::create(description);
  EXPECT_TRUE(created) << (created ? "" : created.error().message);
  if (!created) return {};
  retroaa::Plugin& plugin = *created.value();
  std::vector<uint8_t> display(size_t(kFilterWidth) * kFilterHeight * 4, 255);
  std::vector<uint32_t> depth(size_t(kFilterWidth) * kFilterHeight);
  for (int y = 0; y < kFilterHeight; ++y)
    for (int x = 0; x < kFilterWidth; ++x) {
      const size_t i = size_t(y * kFilterWidth + x);
      const uint8_t grey = x < 8 ? 200 : 30;
      const bool blue = drawnByTheForwardPass(x, y);
      display[i * 4 + 0] = display[i * 4 + 1] = blue ? 0 : grey;
      display[i * 4 + 2] = blue ? 250 : grey;
      depth[i] = uint32_t(double(x < 8 ? 0.5 : 1.0) * 0xFFFFFF) << 8;
    }
  glTextureSubImage2D(t.depthStencil, 0, 0, 0, kFilterWidth, kFilterHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
                      depth.data());
  const std::vector<glm::vec4> normals(size_t(kFilterWidth) * kFilterHeight, glm::vec4(0, 0, 1, 0.5f));
  glTextureSubImage2D(t.normal, 0, 0, 0, kFilterWidth, kFilterHeight, GL_RGBA, GL_FLOAT, normals.data());
  if (plugin.prepassFramebuffer()) {
    writePerSample(plugin.prepassFramebuffer(), kFilterWidth, kFilterHeight,
                   "gl_FragDepth = float(x) + position.x >= 7.6 ? 1.0 : 0.5; outNormal = vec4(0.0, 0.0, 1.0, 0.5);");
  } else {  // stacked on a G-buffer method: its samples (4× standard pattern: samples 1 and 3 lie right of 0.6)
    const SyntheticSample surface = surfaceSample(2.0f), sky = backgroundSample();
    std::vector<std::vector<SyntheticSample>> pixels(size_t(kFilterWidth) * kFilterHeight);
    for (int y = 0; y < kFilterHeight; ++y)
      for (int x = 0; x < kFilterWidth; ++x)
        pixels[size_t(y * kFilterWidth + x)] = x < 7    ? std::vector<SyntheticSample>{surface}
                                               : x == 7 ? std::vector<SyntheticSample>{surface, sky, surface, sky}
                                                        : std::vector<SyntheticSample>{sky};
    fillGeometry(plugin, kFilterWidth, kFilterHeight, pixels);
  }
  EXPECT_TRUE(plugin.resolve({verticalFovFor(0.8f, kFilterWidth, kFilterHeight), 0.1f, 100.0f}));
  EXPECT_TRUE(plugin.shade([](GLuint light) {  // the host's light: one grey
    const float grey[4] = {0.3f, 0.3f, 0.3f, 1.0f};
    glClearNamedFramebufferfv(light, GL_COLOR, 0, grey);
  }));
  {
    const retroaa::Result<retroaa::GLuintHandle> framebuffer = plugin.beginForward();
    EXPECT_TRUE(framebuffer) << (framebuffer ? "" : framebuffer.error().message);
    if (framebuffer) {
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.value());
      glViewport(0, 0, kFilterWidth, kFilterHeight);
      const glm::vec2 size(kFilterWidth, kFilterHeight);
      if (film) {
        glEnable(GL_BLEND);
        glBlendColor(0, 0, 0, 0.1f);
        glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
        drawForwardTriangle({{0, 0}, {16, 0}, {0, 8}}, 0.0f, {1, 1, 1}, size);
        drawForwardTriangle({{16, 0}, {16, 8}, {0, 8}}, 0.0f, {1, 1, 1}, size);
        glDisable(GL_BLEND);
      } else {  // the particle: pixel column 8, rows 2 to 5
        drawForwardTriangle({{8, 2}, {9, 2}, {8, 6}}, 0.0f, {0, 0, 8}, size);
        drawForwardTriangle({{9, 2}, {9, 6}, {8, 6}}, 0.0f, {0, 0, 8}, size);
      }
    }
    EXPECT_TRUE(plugin.endForward());
  }
  // The host's tonemap: the display as above (the forward pass's pixels blue).
  glTextureSubImage2D(t.displayTexture, 0, 0, 0, kFilterWidth, kFilterHeight, GL_RGBA, GL_UNSIGNED_BYTE,
                      display.data());
  EXPECT_TRUE(plugin.post());
  std::vector<uint8_t> out(display.size());
  glGetTextureImage(t.displayTexture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(out.size()), out.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return out;
}

TEST(WholeFrame, PostFiltersSpreadNoColourAForwardPassDrew) {
  for (const char* spec : {"reconstruct", "coverage", "resolve+reconstruct", "resolve+coverage"}) {
    const std::vector<uint8_t> out = filteredBesideAForwardPass(spec, true);
    ASSERT_EQ(out.size(), size_t(kFilterWidth) * kFilterHeight * 4) << spec;
    int blended = 0;  // silhouette pixels mixed with the background: the filter ran
    for (int y = 0; y < kFilterHeight; ++y)
      for (int x = 0; x < kFilterWidth; ++x) {
        const uint8_t* p = &out[size_t(y * kFilterWidth + x) * 4];
        if (drawnByTheForwardPass(x, y)) {
          EXPECT_EQ(p[2], 250) << spec << ": the particle at " << x << ", " << y << " as drawn";
          EXPECT_EQ(p[0], 0) << spec << ": the particle at " << x << ", " << y << " as drawn";
        } else {
          EXPECT_EQ(p[2], p[0]) << spec << ": no blue in the grey pixel " << x << ", " << y;
        }
        blended += x == 7 && p[0] > 40 && p[0] < 190;
      }
    // coverage keeps a silhouette pixel whose tap would read the particle (rows 1 to 5); reconstruct finds
    // the background's colour farther out.
    EXPECT_GE(blended, 3) << spec << ": the silhouette column is still filtered away from the particle";
  }
  // The control: the same frame from a layout that does not say it draws forward passes, where the filters
  // cannot know, pulls the particle's blue into the silhouette pixels beside it.
  for (const char* spec : {"reconstruct", "coverage", "resolve+reconstruct", "resolve+coverage"}) {
    const std::vector<uint8_t> out = filteredBesideAForwardPass(spec, false);
    ASSERT_EQ(out.size(), size_t(kFilterWidth) * kFilterHeight * 4) << spec;
    int tinted = 0;
    for (int y = 2; y <= 5; ++y)
      tinted += out[size_t(y * kFilterWidth + 7) * 4 + 2] > out[size_t(y * kFilterWidth + 7) * 4] + 20;
    EXPECT_GE(tinted, 2) << spec;
  }
}

TEST(WholeFrame, PostFiltersRebuildEdgesUnderAFilmAForwardPassDrew) {
  // A faint particle's smoke or a haze over a silhouette changes every pixel alike: the filters still rebuild
  // the silhouette under it (when any change froze a pixel, STK's exhaust smoke over the kart kept its
  // outline jagged under reconstruct: olivermath 26.20 -> 24.95 dB edge PSNR with particles on).
  for (const char* spec : {"reconstruct", "coverage", "resolve+reconstruct", "resolve+coverage"}) {
    const std::vector<uint8_t> out = filteredBesideAForwardPass(spec, true, true);
    ASSERT_EQ(out.size(), size_t(kFilterWidth) * kFilterHeight * 4) << spec;
    int blended = 0;
    for (int y = 0; y < kFilterHeight; ++y)
      blended += out[size_t(y * kFilterWidth + 7) * 4] > 40 && out[size_t(y * kFilterWidth + 7) * 4] < 190;
    EXPECT_GE(blended, 6) << spec << ": the silhouette column under the film is filtered";
  }
}
