// `temporal`: the jitter sequence and how the hosts apply it, a still frame converging, and the history
// rejected where it must be (a cut, a surface that was not there, a frame without matrices), on
// hand-written G-buffers and on both in-repo hosts.
#include "second_host_patch.h"
#include "test_support.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace testing_support;

namespace {

// The radical inverse of `index` in `base` (Halton's sequence), written from its definition.
float radicalInverse(uint32_t index, uint32_t base) {
  double digitWeight = 1.0, value = 0.0;
  for (; index; index /= base) value += (digitWeight /= base) * (index % base);
  return float(value);
}

// How many of the plugin's warnings contain `text`.
long warningCount(const retroaa::Plugin& plugin, const std::string& text) {
  const std::vector<std::string> warnings = plugin.warnings();
  return long(std::count_if(warnings.begin(), warnings.end(),
                            [&text](const std::string& w) { return w.find(text) != std::string::npos; }));
}
bool warned(const retroaa::Plugin& plugin, const std::string& text) { return warningCount(plugin, text) > 0; }

double maxDifference(const app::DisplayImage& a, const app::DisplayImage& b) {
  double most = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) most = std::max(most, double(std::fabs(a.rgb[i] - b.rgb[i])));
  return most;
}

// A still camera over a hand-written G-buffer (the FSO-shaped host's layout, lit by albedoAsLight), one
// frame at a time, the temporal pass included; the light target (temporal before tonemapping) read back.
struct HandWrittenFrames {
  SyntheticFrame frame{8, 8};
  std::unique_ptr<patch::RetroaaHooks> hooks;
  retroaa::FrameInfo info;
  std::string irradiance = "1.0";  // albedoAsLight's: the light is albedo × this (GLSL)

  explicit HandWrittenFrames(retroaa::Config config = {}) {
    config.method = retroaa::Method::Temporal;
    hooks = frame.attach(config);
    info.verticalFovRadians = 1.0f;
    info.nearPlane = 0.1f;  // surfaceSample's logarithmic depth
    info.farPlane = 2.0e6f;
    const glm::mat4 projection = glm::perspective(1.0f, 1.0f, 0.1f, 2.0e6f);
    std::memcpy(info.projectionMatrix, glm::value_ptr(projection), sizeof info.projectionMatrix);
  }
  std::vector<glm::vec4> run(const std::vector<std::vector<SyntheticSample>>& pixels) {
    retroaa::Plugin& plugin = hooks->plugin();
    fillGeometry(plugin, frame.width, frame.height, pixels);
    EXPECT_TRUE(plugin.resolve(info));
    const GLuint color = frame.renderer->targets().color;
    EXPECT_TRUE(
        plugin.shade([&](GLuint target) { albedoAsLight(color, target, frame.width, frame.height, irradiance); }));
    EXPECT_TRUE(plugin.post());
    info.cameraCut = false;
    return frame.read(frame.renderer->targets().lightTexture);
  }
};

const glm::vec3 kRed(1, 0, 0), kBlue(0, 0, 1);

// Every pixel at `depth` metres; columns from `firstColumn` on at `otherDepth` in red and blue alternating.
std::vector<std::vector<SyntheticSample>> wall(float depth, glm::vec3 albedo, int firstColumn = 8,
                                               float otherDepth = 0) {
  std::vector<std::vector<SyntheticSample>> pixels(64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      pixels[size_t(y * 8 + x)] = {x < firstColumn ? surfaceSample(depth, {0, 0, 1}, albedo)
                                                   : surfaceSample(otherDepth, {0, 0, 1}, (x + y) % 2 ? kRed : kBlue)};
  return pixels;
}

}  // namespace

TEST(Temporal, JitterIsHaltonTwoThreeOverItsLengthAndZeroForOtherMethods) {
  retroaa::Config config;
  config.temporalMovingJitterScale = 1.0f;  // the sequence itself: a new history is short, and would narrow it
  HandWrittenFrames frames(config);
  retroaa::Plugin& plugin = frames.hooks->plugin();
  EXPECT_EQ(plugin.textureLodBias(), -1.0f);
  const auto red = wall(10, kRed);
  for (int frame = 0; frame < 20; ++frame) {
    const retroaa::Jitter jitter = plugin.jitter();
    const uint32_t index = uint32_t(frame % 8) + 1;  // the sequence's first point is index 1: index 0 is (0, 0)
    EXPECT_FLOAT_EQ(jitter.x, radicalInverse(index, 2) - 0.5f) << "frame " << frame;
    EXPECT_FLOAT_EQ(jitter.y, radicalInverse(index, 3) - 0.5f) << "frame " << frame;
    frames.run(red);
  }
  retroaa::Config other;
  other.method = retroaa::Method::Resolve;
  ASSERT_TRUE(plugin.reconfigure(other));
  EXPECT_EQ(plugin.jitter().x, 0.0f);
  EXPECT_EQ(plugin.jitter().y, 0.0f);
  EXPECT_EQ(plugin.textureLodBias(), 0.0f);
  other.temporalFilter = true;  // resolve+temporal jitters too, from the sequence's first point again
  ASSERT_TRUE(plugin.reconfigure(other));
  EXPECT_FLOAT_EQ(plugin.jitter().x, radicalInverse(1, 2) - 0.5f);
  EXPECT_FLOAT_EQ(plugin.jitter().y, radicalInverse(1, 3) - 0.5f);
}

// The mip bias follows how much of the frame keeps a long history: temporal_lod_bias while the view is
// still, temporal_moving_lod_bias once every pixel's history is shorter than the jitter sequence (its blend
// weight raised by the motion; counted by the pass, read frames later), and back when the view stops.
TEST(Temporal, TheMipBiasFollowsTheViewsMotion) {
  retroaa::Config config;
  config.temporalLodBias = -1.0f;
  config.temporalMovingLodBias = -0.25f;
  HandWrittenFrames frames(config);
  retroaa::Plugin& plugin = frames.hooks->plugin();
  const auto red = wall(10, kRed);
  for (int i = 0; i < 12; ++i) frames.run(red);
  EXPECT_FLOAT_EQ(plugin.textureLodBias(), -1.0f) << "a still view";
  // A pixel is 2·10·tan(0.5)/8 = 1.37 m wide at the wall: the camera steps 1 m a frame, 0.73 pixel.
  for (int i = 0; i < 12; ++i) {
    frames.info.viewMatrix[12] -= 1.0f;
    frames.run(red);
  }
  EXPECT_NEAR(plugin.textureLodBias(), -0.25f, 0.01f) << "every pixel moving";
  for (int i = 0; i < 12; ++i) frames.run(red);
  EXPECT_FLOAT_EQ(plugin.textureLodBias(), -1.0f) << "still again";
  // A slow pan (a tenth of a pixel a frame) keeps the still bias: its history accumulates.
  for (int i = 0; i < 12; ++i) {
    frames.info.viewMatrix[12] -= 0.137f;
    frames.run(red);
  }
  EXPECT_GT(plugin.textureLodBias(), -1.0f - 1e-6f);
  EXPECT_LT(plugin.textureLodBias(), -0.85f) << "a slow pan";
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The jitter narrows as the mip bias moves: to temporal_moving_jitter_scale of the Halton point once every
// pixel's history is shorter than the sequence (too short to average its phases), the full point while the
// view is still; counted by the pass, read frames later.
TEST(Temporal, TheJitterNarrowsWhileTheViewMoves) {
  retroaa::Config config;
  config.temporalMovingJitterScale = 0.5f;
  HandWrittenFrames frames(config);
  retroaa::Plugin& plugin = frames.hooks->plugin();
  const auto red = wall(10, kRed);
  int framesRun = 0;
  // The next frame's Halton point (index 1 first) times `scale`, against what the plugin answers.
  auto expectJitter = [&](float scale, float tolerance, const char* view) {
    const uint32_t index = uint32_t(framesRun % 8) + 1;
    const retroaa::Jitter jitter = plugin.jitter();
    EXPECT_NEAR(jitter.x, scale * (radicalInverse(index, 2) - 0.5f), tolerance) << view << ", frame " << framesRun;
    EXPECT_NEAR(jitter.y, scale * (radicalInverse(index, 3) - 0.5f), tolerance) << view << ", frame " << framesRun;
  };
  for (; framesRun < 12; ++framesRun) frames.run(red);
  for (int i = 0; i < 8; ++i, ++framesRun) {
    expectJitter(1.0f, 1e-6f, "a still view");
    frames.run(red);
  }
  // 0.73 pixel a frame at the wall (TheMipBiasFollowsTheViewsMotion): every pixel's history is short.
  for (int i = 0; i < 12; ++i, ++framesRun) {
    frames.info.viewMatrix[12] -= 1.0f;
    frames.run(red);
  }
  for (int i = 0; i < 8; ++i, ++framesRun) {
    expectJitter(0.5f, 0.005f, "every pixel moving");
    frames.info.viewMatrix[12] -= 1.0f;
    frames.run(red);
  }
  for (; framesRun < 60; ++framesRun) frames.run(red);
  expectJitter(1.0f, 1e-6f, "still again");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Temporal, AStillWallConvergesAndACutStartsAgainFromTheCurrentFrame) {
  HandWrittenFrames frames;
  std::vector<glm::vec4> light;
  for (int i = 0; i < 12; ++i) light = frames.run(wall(10, kRed));
  for (const glm::vec4& pixel : light) EXPECT_NEAR(pixel.r, 1.0f, 1e-3f);
  // The same surface turns into a red and blue checkerboard (a box around every pixel's neighbourhood
  // holds red): without a cut the red history weighs in the blue pixels; after one, every pixel shows
  // exactly what was lit.
  light = frames.run(wall(10, kRed, 0, 10.0f));
  EXPECT_GT(light[0].r, 0.5f) << "the history should carry into a frame without a cut";
  for (int i = 0; i < 12; ++i) frames.run(wall(10, kRed));
  frames.info.cameraCut = true;
  light = frames.run(wall(10, kRed, 0, 10.0f));
  for (int i = 0; i < 64; ++i) EXPECT_EQ(glm::vec3(light[size_t(i)]), (i / 8 + i % 8) % 2 ? kRed : kBlue) << i;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Temporal, ALeftHandedProjectionReprojectsAsWell) {
  // Irrlicht's (SuperTuxKart's) projections look down +z: clip w = +z. A still wall still converges.
  HandWrittenFrames frames;
  const glm::mat4 projection = glm::perspectiveLH(1.0f, 1.0f, 0.1f, 2.0e6f);
  std::memcpy(frames.info.projectionMatrix, glm::value_ptr(projection), sizeof frames.info.projectionMatrix);
  for (int i = 0; i < 12; ++i) frames.run(wall(10, kRed));
  const std::vector<glm::vec4> light = frames.run(wall(10, kRed, 0, 10.0f));
  EXPECT_GT(light[0].r, 0.5f) << "the red history should weigh in the blue pixel";
}

TEST(Temporal, ASurfaceThatWasNotThereTakesNoHistory) {
  // Frames written at the pixels' centres: no jitter, so the frame shown where the history is gone (this
  // frame resampled at the centres) is the frame as written.
  retroaa::Config unjittered;
  unjittered.temporalJitterLength = 1;
  HandWrittenFrames frames(unjittered);
  for (int i = 0; i < 12; ++i) frames.run(wall(10, kRed));
  // Columns 4.. now show a nearer surface, red and blue in a checkerboard: the neighbourhood's box holds
  // red, so only the depth test keeps the red history out of the blue pixels.
  const std::vector<glm::vec4> light = frames.run(wall(10, kRed, 4, 5.0f));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const glm::vec4& pixel = light[size_t(y * 8 + x)];
      const glm::vec3 expected = x < 4 || (x + y) % 2 ? kRed : kBlue;
      // The old surface keeps its (red) history; the new one is exactly this frame.
      if (x >= 4) {
        EXPECT_EQ(glm::vec3(pixel), expected) << x << "," << y;
      } else if (x < 3) {
        EXPECT_NEAR(pixel.r, 1.0f, 1e-3f) << x << "," << y;
      }
    }
  // The same change at the old depth is no disocclusion: the red history weighs in the blue pixels.
  for (int i = 0; i < 12; ++i) frames.run(wall(10, kRed));
  const std::vector<glm::vec4> sameDepth = frames.run(wall(10, kRed, 4, 10.0f));
  EXPECT_GT(sameDepth[size_t(0 * 8 + 4)].r, 0.5f);
}

// Where the history is gone, a pixel shows this frame at its centre, resampled from the samples the jitter
// moved off it: a new surface whose light is a ramp across the view, written where each pixel's sample lies
// (its centre plus the jitter; glm's right-handed projection), is shown at the ramp's value at the centres.
TEST(Temporal, WhereTheHistoryIsGoneThePixelShowsThisFrameAtItsCentre) {
  HandWrittenFrames frames;
  for (int i = 0; i < 10; ++i) frames.run(wall(10, kRed));
  const retroaa::Jitter jitter = frames.hooks->plugin().jitter();
  ASSERT_GT(std::fabs(jitter.x), 0.2f);  // frame 11 of Halton (2, 3): off the centre by a quarter pixel or more
  const auto ramp = [](float x) { return glm::vec3(0.1f + 0.1f * x, 0, 0); };
  std::vector<std::vector<SyntheticSample>> nearer(64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) nearer[size_t(y * 8 + x)] = {surfaceSample(5, {0, 0, 1}, ramp(x + 0.5f + jitter.x))};
  const std::vector<glm::vec4> light = frames.run(nearer);
  for (int y = 2; y < 6; ++y)
    for (int x = 2; x < 6; ++x) {  // away from the borders, where the resampling clamps to the edge
      const float shown = light[size_t(y * 8 + x)].r;
      EXPECT_NEAR(shown, ramp(x + 0.5f).r, 0.005f) << x << "," << y;  // Lanczos-2 bends a ramp a little
      EXPECT_GT(std::fabs(shown - ramp(x + 0.5f + jitter.x).r), 0.015f) << x << "," << y;  // not as sampled
    }
}

TEST(Temporal, WithoutMatricesOrWithBrokenOnesEachFrameIsShownAsRenderedWithOneWarning) {
  HandWrittenFrames frames;
  std::memset(frames.info.projectionMatrix, 0, sizeof frames.info.projectionMatrix);
  frames.run(wall(10, kRed));
  std::vector<glm::vec4> light;
  for (int i = 0; i < 3; ++i) light = frames.run(wall(10, kBlue));
  for (const glm::vec4& pixel : light) EXPECT_EQ(glm::vec3(pixel), kBlue);
  EXPECT_EQ(warningCount(frames.hooks->plugin(), "projectionMatrix is not set"), 1);
  // NaN in the view: no history, finite pixels, one warning.
  const glm::mat4 projection = glm::perspective(1.0f, 1.0f, 0.1f, 2.0e6f);
  std::memcpy(frames.info.projectionMatrix, glm::value_ptr(projection), sizeof frames.info.projectionMatrix);
  frames.info.viewMatrix[12] = std::nanf("");
  for (int i = 0; i < 2; ++i) light = frames.run(wall(10, kRed));
  for (const glm::vec4& pixel : light) EXPECT_EQ(glm::vec3(pixel), kRed);
  EXPECT_TRUE(warned(frames.hooks->plugin(), "singular, not finite or not a perspective projection"));
}

// FrameInfo::movingObjects: a pixel whose surface lies inside an object's box reprojects with the object.
// On a still checkerboard the camera alone reads each pixel's own history; a box that was one pixel to the
// right a frame ago (1.37 m at 10 m) reads its neighbour's, the other colour, which the clip lets through
// (both colours are in every neighbourhood). Too many objects, or a box that is not finite, are warned
// about once and change nothing else.
TEST(Temporal, AMovingObjectsBoxReprojectsItsSurfacesWithTheObject) {
  HandWrittenFrames frames;
  const auto board = wall(10, kRed, 0, 10);
  for (int i = 0; i < 8; ++i) frames.run(board);
  const std::vector<glm::vec4> still = frames.run(board);
  const glm::mat4 box = glm::scale(glm::translate(glm::mat4(1.0f), {0, 0, -10}), {100, 100, 1});
  retroaa::MovingObject moved;
  std::memcpy(moved.boxToWorld, glm::value_ptr(box), sizeof moved.boxToWorld);
  const float pixelMetres = 2.0f * 10.0f * std::tan(0.5f) / 8.0f;
  const glm::mat4 before = glm::translate(glm::mat4(1.0f), {pixelMetres, 0, 0}) * box;
  std::memcpy(moved.previousBoxToWorld, glm::value_ptr(before), sizeof moved.previousBoxToWorld);
  frames.info.movingObjects = {moved};
  const std::vector<glm::vec4> followed = frames.run(board);
  for (int x = 2; x < 6; ++x) {  // away from the borders, where the history is clamped to the edge
    const size_t p = size_t(3 * 8 + x);
    EXPECT_GT(glm::length(glm::vec3(followed[p]) - glm::vec3(still[p])), 0.1f) << "column " << x;
  }
  // 20 objects, the nearest (a NaN one among them) first: one warning each, and the frame still renders.
  retroaa::MovingObject broken = moved;
  broken.boxToWorld[0] = std::nanf("");
  frames.info.movingObjects.assign(20, moved);
  frames.info.movingObjects[0] = broken;
  for (int i = 0; i < 3; ++i)
    for (const glm::vec4& pixel : frames.run(board)) EXPECT_TRUE(std::isfinite(pixel.r + pixel.g + pixel.b));
  EXPECT_EQ(warningCount(frames.hooks->plugin(), "20 moving objects in one frame"), 1);
  EXPECT_EQ(warningCount(frames.hooks->plugin(), "box transform is singular or not finite"), 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// NaN or infinite light (a host's division by zero, say) reaches neither the display nor the history:
// such a pixel shows 0 for the frame and starts a new history on the next; the host hears of it once,
// read back frames later (no wait in the frame path).
TEST(Temporal, ANonFiniteLightIsNeitherShownNorKeptAndWarnsOnce) {
  HandWrittenFrames frames;
  for (int i = 0; i < 8; ++i) frames.run(wall(10, kRed));
  for (int round = 0; round < 2; ++round) {
    // The left two columns NaN, the top row infinite.
    frames.irradiance =
        "(gl_FragCoord.x < 2.0 ? uintBitsToFloat(0x7fc00000u) : gl_FragCoord.y > 7.0 ? uintBitsToFloat(0x7f800000u) "
        ": 1.0)";
    std::vector<glm::vec4> light = frames.run(wall(10, kBlue));
    for (const glm::vec4& pixel : light) EXPECT_TRUE(std::isfinite(pixel.r + pixel.g + pixel.b)) << pixel.r;
    EXPECT_EQ(glm::vec3(light[size_t(3 * 8 + 0)]), glm::vec3(0.0f));
    frames.irradiance = "1.0";
    light = frames.run(wall(10, kBlue));
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 2; ++x) EXPECT_EQ(glm::vec3(light[size_t(y * 8 + x)]), kBlue) << x << "," << y;
    for (int i = 0; i < 4; ++i) frames.run(wall(10, kBlue));
    EXPECT_EQ(warningCount(frames.hooks->plugin(), "were not finite"), 1);
  }
}

TEST(Temporal, TheFsoHostJittersItsProjectionAndAStillFrameConvergesNearSupersampling) {
  PatchedHost host("default", 160, 120);
  const ScoringTruth truth = host.scoringTruth(4);
  // With blend 1 the output is the current frame: the host's stock frame at the same jitter and mip bias.
  retroaa::Config passThrough;
  passThrough.temporalBlend = 1.0f;
  host.render("temporal", passThrough);
  const retroaa::Jitter next = host.hooks->plugin().jitter();
  ASSERT_NE(next.x, 0.0f);
  const app::DisplayImage jittered = host.render("temporal", passThrough);
  host.renderer->setStockPath(true);
  host.renderer->setTextureLodBias(-1.0f);
  host.renderer->renderFrame(host.scene.camera, glm::vec2(next.x, next.y));
  const app::DisplayImage stock = app::DisplayImage::fromRgba8(160, 120, host.renderer->readDisplay());
  host.renderer->renderFrame(host.scene.camera);
  const app::DisplayImage unjittered = app::DisplayImage::fromRgba8(160, 120, host.renderer->readDisplay());
  host.renderer->setTextureLodBias(0.0f);
  host.renderer->setStockPath(false);
  EXPECT_LE(maxDifference(jittered, stock), 1.0 / 255.0 + 1e-6);
  EXPECT_GT(maxDifference(jittered, unjittered), 0.1) << "the jitter should move the image";

  const double off = truth.score(host.render("off")).psnrDb;
  const double ssaa = truth.score(host.render("ssaa@supersample=2")).psnrDb;
  retroaa::Config temporal;
  temporal.method = retroaa::Method::Temporal;
  ASSERT_TRUE(host.hooks->plugin().reconfigure(temporal));
  std::vector<double> psnr;
  for (int frame = 0; frame < 40; ++frame) {
    host.renderer->renderFrame(host.scene.camera);
    psnr.push_back(truth.score(app::DisplayImage::fromRgba8(160, 120, host.renderer->readDisplay())).psnrDb);
  }
  EXPECT_GT(psnr.back(), off + 2.0) << "off " << off;
  EXPECT_GT(psnr.back(), ssaa - 1.0) << "ssaa@supersample=2 " << ssaa;
  // Converged: the last round of the jitter sequence scores as the one before (a single frame swings a
  // few tenths of a dB with the newest sample's position).
  double lastRound = 0, roundBefore = 0;
  for (int frame = 0; frame < 8; ++frame)
    lastRound += psnr[size_t(32 + frame)] / 8, roundBefore += psnr[size_t(24 + frame)] / 8;
  EXPECT_NEAR(lastRound, roundBefore, 0.1) << "converged";
  // Switched off, it holds nothing more than before and left no GL error.
  const int objectsOff = [&] {
    host.render("off");
    return host.hooks->plugin().stats().glObjectsHeld;
  }();
  host.render("temporal");
  EXPECT_GT(host.hooks->plugin().stats().bytesHeld, 0u);
  host.render("off");
  EXPECT_EQ(host.hooks->plugin().stats().glObjectsHeld, objectsOff);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Temporal, TheSecondHostJittersAndAccumulatesAfterTonemappingWhereItLightsIntoTheDisplay) {
  context();
  host::Scene scene = host::loadScene("default");
  host::SecondRenderer renderer(scene, 160, 120);
  retroaa::Config config;
  config.method = retroaa::Method::Temporal;
  auto created = patch::SecondHostHooks::create(renderer.targets(), config);
  ASSERT_TRUE(created) << created.error().message;
  patch::SecondHostHooks& hooks = *created.value();
  renderer.setSeams(&hooks);
  // The documented window-lit pattern: where it accumulates follows from the layout, with no warning.
  EXPECT_FALSE(warned(hooks.plugin(), "accumulating the display after tonemapping instead"));
  const host::GroundTruth truth = host::renderGroundTruth(renderer, scene.camera, 4);
  const app::DisplayImage reference = app::DisplayImage::fromRgba8(160, 120, truth.display);
  const std::vector<uint8_t> edges = app::edgeMaskFromSpread(truth.lumaStdDev);
  auto score = [&] {
    return app::compare(app::DisplayImage::fromRgba8(160, 120, renderer.readDisplay()), reference, edges).psnrDb;
  };
  renderer.setSeams(nullptr);
  renderer.renderFrame(scene.camera);
  const double off = score();
  renderer.setSeams(&hooks);
  for (int frame = 0; frame < 40; ++frame) renderer.renderFrame(scene.camera);
  EXPECT_GT(score(), off + 2.0);
  EXPECT_TRUE(hooks.lastError().empty()) << hooks.lastError();
  renderer.setSeams(nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The built-in temporal.frag with each `from` replaced by its `to`, as a shader override folder.
std::string temporalShaderVariant(const std::string& name,
                                  const std::vector<std::pair<std::string, std::string>>& replacements) {
  return writeShaderOverride("retroaa_temporal_" + name, "temporal/temporal.frag", replacements);
}

TEST(Temporal, AMovingCameraReprojectsTheHistoryOntoTheSameSurfaces) {
  // No jitter, no mip bias and no clip (a shader override): every frame is the stock frame and only the
  // reprojection keeps the history on the right surfaces. Reprojected, the output stays near the frame
  // itself (the history resampled, a little blurred); read where the pixel is now instead, it trails.
  const std::string clip = "if (outside > 1.0) h = centre + toHistory / outside;";
  const std::string noClip = temporalShaderVariant("no_clip", {{clip, ""}});
  const std::string noClipNoMotion =
      temporalShaderVariant("no_clip_no_motion", {{clip, ""},
                                                  {"vec2 previousUv = previousClip.xy / previousClip.w * 0.5 + 0.5;",
                                                   "vec2 previousUv = (vec2(pixel) + 0.5) / vec2(last + 1);"}});
  PatchedHost host("default", 160, 120);
  auto closenessToItsFrame = [&](const std::string& overrides) {
    retroaa::Config config;
    config.method = retroaa::Method::Temporal;
    config.temporalJitterLength = 1;
    config.temporalLodBias = 0;
    config.temporalBlend = 0.5f;
    config.shaderOverrideDirectory = overrides;
    EXPECT_TRUE(host.hooks->plugin().reconfigure(config));
    host::Camera camera = host.scene.camera;
    const glm::vec3 forward = camera.target - camera.position;
    for (int frame = 0; frame <= 12; ++frame) {  // turning about 4 pixels a frame, and moving sideways
      const float yaw = 0.02f * float(frame);
      camera.target = camera.position + glm::vec3(std::cos(yaw) * forward.x - std::sin(yaw) * forward.z, forward.y,
                                                  std::sin(yaw) * forward.x + std::cos(yaw) * forward.z);
      camera.position += glm::vec3(0.05f, 0.0f, 0.0f);
      host.renderer->renderFrame(camera);
    }
    const app::DisplayImage temporal = app::DisplayImage::fromRgba8(160, 120, host.renderer->readDisplay());
    host.render("off");
    host.renderer->renderFrame(camera);
    return app::compare(temporal, app::DisplayImage::fromRgba8(160, 120, host.renderer->readDisplay()), {}).psnrDb;
  };
  const double reprojected = closenessToItsFrame(noClip), inPlace = closenessToItsFrame(noClipNoMotion);
  EXPECT_GT(reprojected, inPlace + 1.0) << "in place " << inPlace;
  EXPECT_GT(reprojected, 25.0);
}

// `+temporal` on every slice method: the composed light of all slices is the frame's light, and the
// history accumulates it as it does a single slice's (it once ran only on the single-slice path, so a
// slice method stacked with it jittered without accumulating: below both of its parts). On the still demo
// frame, after the jitter sequence twice over, each stack's edge PSNR is at least its base's.
TEST(Temporal, StackedOnEverySliceMethodItIsAtLeastItsBase) {
  PatchedHost host("default", 96, 72);
  const ScoringTruth truth = host.scoringTruth(4);
  for (const char* base : {"edge", "per-sample", "adaptive", "aggregate", "smaa-s2x"}) {
    const double alone = truth.score(host.render(base)).edgePsnrDb;
    app::DisplayImage stacked = host.render(std::string(base) + "+temporal");
    for (int frame = 0; frame < 16; ++frame) stacked = host.render(std::string(base) + "+temporal");
    const double withHistory = truth.score(stacked).edgePsnrDb;
    std::printf("%s: edge PSNR %.2f alone, %.2f with +temporal\n", base, alone, withHistory);
    EXPECT_GE(withHistory, alone - 0.05) << base;
  }
}

// Every post filter the config stacks on a method (+smaa, +coverage, +reconstruct, +fxaa) on the bases
// it serves: at least the base's PSNR on the demo frame's model edges. (On all its edges `+fxaa` over a
// slice method is below its base: every loss is at the stars, which FXAA blurs as edges; on the models'
// edges it gains. docs/methods/fxaa.md.)
TEST(Stacks, EveryStackedFilterIsAtLeastItsBaseOnTheDemosModelEdges) {
  PatchedHost host("default", 96, 72);
  const ScoringTruth truth = host.scoringTruth(4, host::BackgroundEdges::Apart);
  ASSERT_FALSE(truth.modelEdges.empty()) << "the demo's stars were not told apart";
  for (const char* base : {"resolve", "edge", "adaptive"}) {
    const double alone = truth.scoreModelEdges(host.render(base)).edgePsnrDb;
    for (const char* filter : {"+smaa", "+coverage", "+reconstruct", "+fxaa"}) {
      const std::string stack = std::string(base) + filter;
      const app::DisplayImage image = host.render(stack);
      const double stacked = truth.scoreModelEdges(image).edgePsnrDb;
      std::printf("%s: model-edge PSNR %.2f, %s %.2f (all edges %.2f)\n", base, alone, stack.c_str(), stacked,
                  truth.score(image).edgePsnrDb);
      EXPECT_GE(stacked, alone - 0.02) << stack;
    }
  }
}
