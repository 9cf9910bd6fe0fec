#include "test_support.h"

#include "commands.h"
#include "depth_codec.h"

#include <sys/wait.h>
#include <unistd.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace testing_support {

host::HeadlessContext& context() {
  static host::HeadlessContext instance;
  return instance;
}

std::string testDataPath(const std::string& relative) { return std::string(RETROAA_TEST_DATA) + "/" + relative; }

PatchedHost::PatchedHost(const std::string& scenePath, int width, int height)
    : PatchedHost(host::loadScene(scenePath), width, height) {}

PatchedHost::PatchedHost(host::Scene loaded, int width, int height) : scene(std::move(loaded)) {
  context();
  renderer = std::make_unique<host::Renderer>(scene, width, height);
  auto created = patch::RetroaaHooks::create(renderer->targets(), retroaa::Config{});
  if (!created) throw std::runtime_error(created.error().message);
  hooks = std::move(created.value());
  renderer->setHooks(hooks.get());
}

app::DisplayImage PatchedHost::render(const std::string& methodSpec, const retroaa::Config& base) {
  const retroaa::Status status = hooks->plugin().reconfigure(app::parseMethodSpec(methodSpec, base).config);
  if (!status) throw std::runtime_error(status.error().message);
  renderer->renderFrame(scene.camera);
  return app::DisplayImage::fromRgba8(renderer->width(), renderer->height(), renderer->readDisplay());
}

std::unique_ptr<patch::RetroaaHooks> installHooks(PatchedHost& host, const retroaa::Config& config,
                                                  uint32_t disabledFeatures, int maxSamplesLimit) {
  auto created = patch::RetroaaHooks::create(host.renderer->targets(), config, disabledFeatures, maxSamplesLimit);
  if (!created) throw std::runtime_error(created.error().message);
  host.renderer->setHooks(created.value().get());
  return std::move(created.value());
}

host::GroundTruth PatchedHost::groundTruth(int samplesPerAxis) {
  return host::renderGroundTruth(*renderer, scene.camera, samplesPerAxis);
}

ScoringTruth PatchedHost::scoringTruth(int samplesPerAxis, host::BackgroundEdges backgroundEdges) {
  const host::GroundTruth gt = host::renderGroundTruth(*renderer, scene.camera, samplesPerAxis,
                                                       host::TextureFootprint::Supersample, backgroundEdges);
  return {app::DisplayImage::fromRgba8(gt.width, gt.height, gt.display), app::edgeMaskFromSpread(gt.lumaStdDev),
          gt.modelLumaStdDev.empty() ? std::vector<uint8_t>{} : app::modelEdgeMask(gt.lumaStdDev, gt.modelLumaStdDev)};
}

float throughHalf(float value) { return glm::unpackHalf1x16(glm::packHalf1x16(value)); }

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float linearToSrgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

float verticalFovFor(float horizontalFov, int width, int height) {
  return 2.0f * std::atan(std::tan(horizontalFov * 0.5f) * float(height) / float(width));
}

glm::ivec2 projectToPixel(const host::Camera& camera, glm::vec3 world, int width, int height) {
  const glm::vec4 clip = camera.projection(width, height) * camera.view() * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const int x = static_cast<int>((ndc.x * 0.5f + 0.5f) * width);
  const int yUp = static_cast<int>((ndc.y * 0.5f + 0.5f) * height);
  return {x, height - 1 - yUp};
}

SyntheticSample backgroundSample() {
  return {{glm::vec4(0), glm::vec4(0, 0, host::depth_codec::kBackgroundMarker, 0), glm::vec4(0), glm::vec4(0),
           glm::vec4(0.1f, 0.2f, 0.3f, 1)},
          glm::vec4(1.0f)};
}

SyntheticSample surfaceSample(float depth, glm::vec3 normal, glm::vec3 albedo) {
  return {{glm::vec4(albedo, 1), glm::vec4(0.01f, -0.02f, host::depth_codec::encode(depth), 1), glm::vec4(normal, 0.5f),
           glm::vec4(0.2f, 0.2f, 0.2f, 1), glm::vec4(0, 0, 0, 1)},
          glm::vec4(std::log2(depth / 0.1f) / std::log2(2e7f))};
}

namespace {
GLuint fullscreenVertexProgram() {
  const char* vertex =
      "#version 450 core\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);"
      " gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }";
  return glCreateShaderProgramv(GL_VERTEX_SHADER, 1, &vertex);
}

}  // namespace

void drawTriangleWith(const char* vertexSource, const char* fragmentSource,
                      const std::function<void(GLuint vertex, GLuint fragment)>& setUniforms) {
  const GLuint vertex =
      vertexSource ? glCreateShaderProgramv(GL_VERTEX_SHADER, 1, &vertexSource) : fullscreenVertexProgram();
  const GLuint fragment = glCreateShaderProgramv(GL_FRAGMENT_SHADER, 1, &fragmentSource);
  for (const GLuint program : {vertex, fragment}) {
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
      char log[2048] = {};
      glGetProgramInfoLog(program, sizeof log, nullptr, log);
      ADD_FAILURE() << "test shader does not link: " << log;
    }
  }
  GLuint pipeline = 0, vao = 0;
  glCreateProgramPipelines(1, &pipeline);
  glUseProgramStages(pipeline, GL_VERTEX_SHADER_BIT, vertex);
  glUseProgramStages(pipeline, GL_FRAGMENT_SHADER_BIT, fragment);
  glCreateVertexArrays(1, &vao);
  setUniforms(vertex, fragment);
  glUseProgram(0);
  glBindProgramPipeline(pipeline);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindProgramPipeline(0);
  glDeleteProgramPipelines(1, &pipeline);
  glDeleteProgram(vertex);
  glDeleteProgram(fragment);
  glDeleteVertexArrays(1, &vao);
}

// Draws one full-screen triangle with a separable fragment program; deletes what it made.
void drawWithFragment(const char* fragmentSource, const std::function<void(GLuint)>& setUniforms) {
  drawTriangleWith(nullptr, fragmentSource, [&setUniforms](GLuint, GLuint fragment) { setUniforms(fragment); });
}

void writePerSample(GLuint target, int width, int height, const std::string& body) {
  const std::string fragment =
      "#version 450 core\nlayout(location = 2) out vec4 outNormal;\n"
      "void main() {  // reading gl_SamplePosition runs this once per sample\n"
      "  int x = int(gl_FragCoord.x), y = int(gl_FragCoord.y);\n  vec2 position = gl_SamplePosition;\n" +
      body + "\n}\n";
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  drawWithFragment(fragment.c_str(), [](GLuint) {});
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
}

std::vector<uint8_t> runPrepassFilter(retroaa::Plugin& plugin, GLuint displayTexture, int width, int height,
                                      const std::string& body) {
  EXPECT_NE(plugin.prepassFramebuffer(), 0u);
  writePerSample(plugin.prepassFramebuffer(), width, height, body);
  EXPECT_TRUE(plugin.resolve({verticalFovFor(0.8f, width, height), 0.1f, 100.0f}));
  EXPECT_TRUE(plugin.post());
  std::vector<uint8_t> out(size_t(width) * height * 4);
  glGetTextureImage(displayTexture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(out.size()), out.data());
  return out;
}

StandInDisplay::StandInDisplay(GLenum format, int width, int height) {
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glCreateFramebuffers(1, &framebuffer);
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
}

StandInDisplay::~StandInDisplay() {
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
}

void StandInDisplay::describeIn(retroaa::GBufferLayout& layout) const {
  layout.displayTexture = texture;
  layout.displayFramebuffer = framebuffer;
}

int fillGeometry(retroaa::Plugin& plugin, int width, int height,
                 const std::vector<std::vector<SyntheticSample>>& pixels) {
  const int n = plugin.stats().samples;
  std::vector<SyntheticSample> data(size_t(width) * height * n, backgroundSample());
  for (size_t p = 0; p < pixels.size() && p < size_t(width) * height; ++p)
    if (!pixels[p].empty())
      for (int s = 0; s < n; ++s) data[p * n + s] = pixels[p][s * pixels[p].size() / n];
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, data.size() * sizeof(SyntheticSample), data.data(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, plugin.geometryFramebuffer());
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  drawWithFragment(R"(#version 450 core
layout(std430, binding = 0) readonly buffer Samples { vec4 data[]; };
uniform int uSamples;
uniform int uWidth;
layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;
layout(location = 3) out vec4 out3;
layout(location = 4) out vec4 out4;
void main() {  // reading gl_SampleID runs this once per sample
  ivec2 p = ivec2(gl_FragCoord.xy);
  int base = ((p.y * uWidth + p.x) * uSamples + gl_SampleID) * 6;
  out0 = data[base]; out1 = data[base + 1]; out2 = data[base + 2]; out3 = data[base + 3]; out4 = data[base + 4];
  gl_FragDepth = data[base + 5].x;
})",
                   [&](GLuint program) {
                     glProgramUniform1i(program, glGetUniformLocation(program, "uSamples"), n);
                     glProgramUniform1i(program, glGetUniformLocation(program, "uWidth"), width);
                   });
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glDeleteBuffers(1, &buffer);
  return n;
}

void albedoAsLight(GLuint colorTexture, GLuint target, int width, int height, const std::string& irradiance) {
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, width, height);
  glBindTextureUnit(0, colorTexture);
  const std::string source = R"(#version 450 core
layout(binding = 0) uniform sampler2D uColor;
out vec4 outLight;
void main() { outLight = vec4(texelFetch(uColor, ivec2(gl_FragCoord.xy), 0).rgb * ()" +
                             irradiance + "), 1.0); }";
  drawWithFragment(source.c_str(), [](GLuint) {});
}

SyntheticFrame::SyntheticFrame(int w, int h) : width(w), height(h) {
  context();
  scene = host::parseScene(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
    "materials": [{"name": "m"}], "objects": []})",
                           "empty", ".");
  renderer = std::make_unique<host::Renderer>(scene, width, height);
}

std::unique_ptr<patch::RetroaaHooks> SyntheticFrame::attach(const retroaa::Config& config) {
  auto hooks = patch::RetroaaHooks::create(renderer->targets(), config);
  if (!hooks) {
    ADD_FAILURE() << hooks.error().message;
    return nullptr;
  }
  return std::move(hooks.value());
}

std::unique_ptr<patch::RetroaaHooks> SyntheticFrame::attach(retroaa::Method method) {
  retroaa::Config config;
  config.method = method;
  return attach(config);
}

std::unique_ptr<patch::RetroaaHooks> SyntheticFrame::run(const retroaa::Config& config,
                                                         const std::vector<std::vector<SyntheticSample>>& pixels,
                                                         const std::string& irradiance) {
  auto hooks = attach(config);
  if (!hooks) return nullptr;
  retroaa::Plugin& plugin = hooks->plugin();
  samples = fillGeometry(plugin, width, height, pixels);
  EXPECT_TRUE(plugin.resolve({1.0f}));
  const GLuint color = renderer->targets().color;
  EXPECT_TRUE(plugin.shade([&](GLuint target) { albedoAsLight(color, target, width, height, irradiance); }));
  return hooks;
}

std::vector<glm::vec4> SyntheticFrame::read(GLuint texture) const {
  std::vector<glm::vec4> pixels(size_t(width) * height);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(glm::vec4)), pixels.data());
  return pixels;
}

CliRun runCli(const std::string& arguments) { return runCommand(std::string(RETROAA_CLI) + " " + arguments); }

BenchRun runBench(const std::string& arguments) {
  static int runs = 0;  // each run its own file within this test process
  const std::filesystem::path json =
      std::filesystem::temp_directory_path() /
      ("retroaa_bench_" + std::to_string(getpid()) + "_" + std::to_string(++runs) + ".json");
  BenchRun bench{runCli("bench " + arguments + " --json " + json.string()), nullptr};
  if (bench.run.exitCode == 0) bench.document = nlohmann::json::parse(std::ifstream(json));
  std::filesystem::remove(json);
  return bench;
}

CliRun runCommand(const std::string& shellCommand) {
  const std::string command = shellCommand + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string writeShaderOverride(const std::string& folder, const std::string& shader,
                                const std::vector<std::pair<std::string, std::string>>& replacements) {
  std::ifstream in(std::string(RETROAA_SOURCE_DIR) + "/shaders/" + shader);
  std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(source.empty()) << shader;
  for (const auto& [from, to] : replacements) {
    const size_t at = source.find(from);
    EXPECT_NE(at, std::string::npos) << shader << ": " << from;
    if (at != std::string::npos) source.replace(at, from.size(), to);
  }
  const std::filesystem::path root = std::filesystem::temp_directory_path() / folder;
  const std::filesystem::path file = root / shader;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << source;
  return root.string();
}

}  // namespace testing_support
