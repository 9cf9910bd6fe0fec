// Shared by the integration tests: one headless context per test process, and helpers to render
// the built-in scenes through the host with the engine patch.
#pragma once

#include "ground_truth.h"
#include "headless_context.h"
#include "metrics.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>

namespace testing_support {

// Created on first use, lives until the process exits.
host::HeadlessContext& context();

// `value` as an FP16 target stores it (round to nearest even).
float throughHalf(float value);

// The sRGB transfer functions (IEC 61966-2-1) on values in [0, 1].
float srgbToLinear(float c);
float linearToSrgb(float c);

// Path of a file in integration-tests/ (scenes, fixtures).
std::string testDataPath(const std::string& relative);

// A ground truth as the error metrics use it: its display image and its edge mask.
struct ScoringTruth {
  app::DisplayImage display;
  std::vector<uint8_t> edges;
  std::vector<uint8_t> modelEdges;  // without the background's detail (stars); empty unless asked for
  app::ErrorMetrics score(const app::DisplayImage& image) const { return app::compare(image, display, edges); }
  // Edge figures on the models' edges alone (the edges when the background has no detail or none was asked).
  app::ErrorMetrics scoreModelEdges(const app::DisplayImage& image) const {
    return app::pixelErrors(image, display, modelEdges.empty() ? edges : modelEdges);
  }
};

// A host renderer on a scene with the retroaa patch installed.
struct PatchedHost {
  host::Scene scene;
  std::unique_ptr<host::Renderer> renderer;
  std::unique_ptr<patch::RetroaaHooks> hooks;
  PatchedHost(const std::string& scenePath, int width, int height);
  PatchedHost(host::Scene scene, int width, int height);
  // Renders the scene camera with a method spec (see app::parseMethodSpec) and returns the display.
  app::DisplayImage render(const std::string& methodSpec, const retroaa::Config& base = {});
  host::GroundTruth groundTruth(int samplesPerAxis);
  ScoringTruth scoringTruth(int samplesPerAxis,
                            host::BackgroundEdges backgroundEdges = host::BackgroundEdges::Together);
};

// A fresh plugin for `host` under `config`, on a context with `disabledFeatures` masked and
// GL_MAX_SAMPLES limited to `maxSamplesLimit` (0: the context's), set as the host's hooks. Set
// `host.hooks` back (host.renderer->setHooks(host.hooks.get())) before the returned hooks go.
std::unique_ptr<patch::RetroaaHooks> installHooks(PatchedHost& host, const retroaa::Config& config,
                                                  uint32_t disabledFeatures = 0, int maxSamplesLimit = 0);

// One sample of the FSO layout written by hand: albedo, position, normal+gloss, specular, emissive,
// and the depth-buffer value (x).
struct SyntheticSample {
  glm::vec4 attachments[5];
  glm::vec4 depthBuffer;
};
SyntheticSample backgroundSample();  // the sky (0.1, 0.2, 0.3) in emissive, position = far marker
SyntheticSample surfaceSample(float depthMetres, glm::vec3 normal = {0, 0, 1}, glm::vec3 albedo = glm::vec3(0.5f));

// Writes every sample of every pixel of `plugin`'s geometry framebuffer (a per-sample shader reads
// them from a buffer). `pixels[y * width + x]` lists one pixel's samples (GL's bottom-up rows); pixels
// past the list are background. A list shorter or longer than the allocated sample count is stretched
// over it, keeping its proportions. Returns the allocated sample count.
int fillGeometry(retroaa::Plugin& plugin, int width, int height,
                 const std::vector<std::vector<SyntheticSample>>& pixels);

// Draws one triangle (vertices 0, 1, 2) with separable programs into the bound framebuffer: `vertexSource`
// (null: one covering the viewport) and `fragmentSource`; `setUniforms` gets both programs first.
void drawTriangleWith(const char* vertexSource, const char* fragmentSource,
                      const std::function<void(GLuint vertex, GLuint fragment)>& setUniforms);
// Draws one full-screen triangle with a separable fragment program into the bound framebuffer.
void drawWithFragment(const char* fragmentSource, const std::function<void(GLuint program)>& setUniforms);

// Writes every sample of `target` (depth test ALWAYS): `body` runs once per sample with `int x, y` (the
// pixel) and `vec2 position` (the sample's position in its pixel) and sets gl_FragDepth and, where
// the target keeps one, `outNormal` (location 2).
void writePerSample(GLuint target, int width, int height, const std::string& body);

// One frame of a post filter over a prepass (coverage, reconstruct) on hand-written data: writes every
// sub-sample of plugin.prepassFramebuffer() with `body` (writePerSample), resolves with a horizontal fov of
// 0.8 rad (near 0.1 m, far 100 m), runs post() and reads `displayTexture` back (RGBA8, GL rows).
std::vector<uint8_t> runPrepassFilter(retroaa::Plugin& plugin, GLuint displayTexture, int width, int height,
                                      const std::string& body);

// A stand-in for a host lighting pass: light = albedo (read from the host's colour attachment) times
// `irradiance`, a GLSL float expression that may use gl_FragCoord.
void albedoAsLight(GLuint colorTexture, GLuint target, int width, int height, const std::string& irradiance = "1.0");

// A display texture of `format` (and a framebuffer with it as colour 0) that a test names in a layout in place
// of the host's RGBA8 one; freed with it.
struct StandInDisplay {
  GLuint texture = 0, framebuffer = 0;
  StandInDisplay(GLenum format, int width, int height);
  ~StandInDisplay();
  StandInDisplay(const StandInDisplay&) = delete;
  StandInDisplay& operator=(const StandInDisplay&) = delete;
  void describeIn(retroaa::GBufferLayout& layout) const;  // displayTexture and displayFramebuffer
};

// A host with no scene objects whose G-buffer the tests write by hand: runs one frame of a method on
// hand-written samples, lit by `albedoAsLight`.
struct SyntheticFrame {
  host::Scene scene;
  std::unique_ptr<host::Renderer> renderer;
  int width, height;
  int samples = 0;  // allocated by the last run
  SyntheticFrame(int width, int height);
  // The patch installed on this host with `config`, no frame run yet (a failure is a test failure).
  std::unique_ptr<patch::RetroaaHooks> attach(const retroaa::Config& config);
  std::unique_ptr<patch::RetroaaHooks> attach(retroaa::Method method);  // every other setting its default
  // Resolves and shades `pixels` (see fillGeometry) with `config`; the returned hooks own the plugin.
  std::unique_ptr<patch::RetroaaHooks> run(const retroaa::Config& config,
                                           const std::vector<std::vector<SyntheticSample>>& pixels,
                                           const std::string& irradiance = "1.0");
  std::vector<glm::vec4> read(GLuint texture) const;  // RGBA float, GL's bottom-up rows
};

// A shader override folder (Config::shaderOverrideDirectory) under the temporary directory: `shader`
// (relative to shaders/) as built in, with each `from` replaced by its `to` (a `from` not found is a test
// failure). Returns the folder; several calls with the same `folder` add files to it.
std::string writeShaderOverride(const std::string& folder, const std::string& shader,
                                const std::vector<std::pair<std::string, std::string>>& replacements);

// Runs the `retroaa` binary with `arguments`, capturing stdout and stderr together.
struct CliRun {
  int exitCode;
  std::string output;
};
CliRun runCli(const std::string& arguments);
CliRun runCommand(const std::string& command);  // any shell command
// `retroaa bench ARGUMENTS --json FILE` and the JSON it wrote (null where it failed).
struct BenchRun {
  CliRun run;
  nlohmann::json document;
};
BenchRun runBench(const std::string& arguments);

// The vertical field of view (FrameInfo's) whose horizontal one at width × height is `horizontalFov`.
float verticalFovFor(float horizontalFov, int width, int height);

// The pixel (top-down image coordinates) where a world point lands for the scene camera.
glm::ivec2 projectToPixel(const host::Camera& camera, glm::vec3 world, int width, int height);

}  // namespace testing_support
