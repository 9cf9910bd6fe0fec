// The method registry (one const table: every row parses, prints and reaches the tools) and the
// plugin's error contract: every error code the headers list is provoked here.
#include "commands.h"
#include "shared_constants.h"
#include "technique.h"
#include "test_support.h"

#include <epoxy/egl.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <type_traits>

using namespace testing_support;

namespace {

void expectError(const retroaa::Error& error, retroaa::ErrorCode code, const std::string& fragment) {
  EXPECT_EQ(error.code, code) << error.message;
  EXPECT_NE(error.message.find(fragment), std::string::npos) << error.message;
}

// A description of `host`'s G-buffer, every setting its default.
retroaa::Description describedHost(const PatchedHost& host) {
  retroaa::Description description;
  description.layout = patch::describeHostGBuffer(host.renderer->targets());
  return description;
}

}  // namespace

TEST(Registry, EveryEnumValueHasOneRowAndEveryRowParses) {
  std::set<std::string> names;
  for (const retroaa::MethodInfo& row : retroaa::methodTable()) {
    EXPECT_TRUE(names.insert(row.name).second) << "two rows named " << row.name;
    retroaa::Config config;
    ASSERT_TRUE(retroaa::applySetting(config, "method", row.name)) << row.name;
    EXPECT_EQ(config.method, row.method);
    EXPECT_EQ(retroaa::findMethod(row.method), &row);
    if (*row.stackKey) {  // a switch, and `resolve+NAME` turns it on
      EXPECT_EQ(retroaa::settingValues(row.stackKey), (std::vector<std::string>{"on", "off"})) << row.name;
      EXPECT_EQ(retroaa::readSetting(app::parseMethodSpec(std::string("resolve+") + row.name, {}).config, row.stackKey),
                "on");
    }
    // Every spec a tool renders for the row parses and selects the row's method.
    const app::ToolSpecs tools = app::toolSpecs(row);
    for (const std::string& specs : {tools.sweep, tools.regress, tools.tune})
      for (const std::string& spec : app::expandMethodList(specs)) {
        const retroaa::Config parsed = app::parseMethodSpec(spec, {}).config;
        // (a stacked spec, `resolve+NAME` or `reconstruct+temporal`, turns the row's stack key on instead)
        EXPECT_TRUE(parsed.method == row.method || (spec.find('+') != std::string::npos && *row.stackKey &&
                                                    retroaa::readSetting(parsed, row.stackKey) == "on"))
            << spec;
      }
  }
  EXPECT_EQ(retroaa::findMethod(retroaa::Method(250)), nullptr);
  EXPECT_STREQ(retroaa::toString(retroaa::Method(250)), "?");
}

// The same rules as the text parser, for configs built in code.
TEST(PluginErrors, ACodeBuiltConfigIsCheckedByTheParsersRules) {
  struct Case {
    const char* key;
    void (*spoil)(retroaa::Config&);
  };
  const Case cases[] = {
      {"aggregate_count", [](retroaa::Config& c) { c.aggregateCount = 0; }},
      {"samples", [](retroaa::Config& c) { c.samples = 3; }},
      {"closeness", [](retroaa::Config& c) { c.closeness = std::numeric_limits<float>::quiet_NaN(); }},
      {"fxaa_edge_threshold", [](retroaa::Config& c) { c.fxaaEdgeThreshold = 0.9f; }},
      {"adaptive_min_samples", [](retroaa::Config& c) { c.adaptiveMinSamples = 17; }},
      {"aggregate_length", [](retroaa::Config& c) { c.aggregateLength = 0.0099999f; }},  // just below its floor
      {"method", [](retroaa::Config& c) { c.method = retroaa::Method(250); }},
      {"edge_detector", [](retroaa::Config& c) { c.edgeDetector = retroaa::EdgeDetector(77); }},
  };
  PatchedHost host("default", 32, 24);
  retroaa::Plugin& plugin = host.hooks->plugin();
  ASSERT_TRUE(plugin.reconfigure(app::parseMethodSpec("edge", {}).config));
  const std::string before = retroaa::toConfigText(plugin.config());
  for (const Case& c : cases) {
    retroaa::Config config;
    config.method = retroaa::Method::Resolve;
    c.spoil(config);
    const retroaa::Status checked = retroaa::validateConfig(config);
    ASSERT_FALSE(checked) << c.key;
    expectError(checked.error(), retroaa::ErrorCode::InvalidConfig, std::string("'") + c.key + "'");
    // reconfigure refuses it and changes nothing; create refuses it too.
    const retroaa::Status refused = plugin.reconfigure(config);
    ASSERT_FALSE(refused) << c.key;
    EXPECT_EQ(refused.error().code, retroaa::ErrorCode::InvalidConfig);
    EXPECT_EQ(retroaa::toConfigText(plugin.config()), before);
    auto created = patch::RetroaaHooks::create(host.renderer->targets(), config);
    ASSERT_FALSE(created) << c.key;
    EXPECT_EQ(created.error().code, retroaa::ErrorCode::InvalidConfig);
  }
  // Defaults and every preset are valid.
  EXPECT_TRUE(retroaa::validateConfig(retroaa::Config{}));
  for (const char* preset : {"low", "medium", "high", "ultra"}) {
    retroaa::Config config;
    ASSERT_TRUE(retroaa::applySetting(config, "preset", preset));
    EXPECT_TRUE(retroaa::validateConfig(config)) << preset;
  }
}

TEST(PluginErrors, ShadeWithoutResolveIsAWrongCallOrder) {
  PatchedHost host("default", 32, 24);
  retroaa::Plugin& plugin = host.hooks->plugin();
  int lightingRuns = 0;
  const retroaa::LightingFunction lighting = [&lightingRuns](retroaa::GLuintHandle) { ++lightingRuns; };
  host.render("resolve");  // a whole frame: resolve() then shade()
  const retroaa::Status status = plugin.shade(lighting);
  ASSERT_FALSE(status);
  expectError(status.error(), retroaa::ErrorCode::WrongCallOrder, "resolve()");
  EXPECT_EQ(lightingRuns, 0);
  // Methods without an MSAA G-buffer have nothing to resolve: shading alone is fine.
  host.render("fxaa");
  EXPECT_TRUE(plugin.shade(lighting));
  EXPECT_EQ(lightingRuns, 1);
}

TEST(PluginErrors, ATargetTheDriverRefusesIsAnIncompleteFramebuffer) {
  PatchedHost host("default", 32, 24);
  retroaa::Description description = describedHost(host);
  description.layout.attachments[0].internalFormat = GL_RGB9_E5;  // shared-exponent: not colour-renderable
  description.config.method = retroaa::Method::Resolve;
  auto created = retroaa::Plugin::create(description);
  ASSERT_FALSE(created);
  expectError(created.error(), retroaa::ErrorCode::IncompleteFramebuffer, "attachment 0 (Albedo, format 0x8c3d)");
}

TEST(PluginLayout, UnsizedFormatsTakeTheSizedOnesOfTheHostsOwnObjects) {
  PatchedHost host("default", 32, 24);
  // A specular texture made the old way (unsized GL_RGBA) and a GL_DEPTH_COMPONENT depth renderbuffer.
  GLuint specular = 0, depth = 0;
  glGenTextures(1, &specular);
  glBindTexture(GL_TEXTURE_2D, specular);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 24, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  glCreateRenderbuffers(1, &depth);
  glNamedRenderbufferStorage(depth, GL_DEPTH_COMPONENT, 32, 24);
  retroaa::Description description = describedHost(host);
  description.layout.attachments[3] = {retroaa::AttachmentRole::Specular, GL_RGBA, specular};
  description.layout.depthStencilTexture = 0;
  description.layout.depthStencilRenderbuffer = depth;
  description.config.method = retroaa::Method::Resolve;
  {
    auto created = retroaa::Plugin::create(description);
    ASSERT_TRUE(created) << created.error().message;
    EXPECT_TRUE(created.value()->resolve({}));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  // Declared unsized over a texture whose format cannot be rendered into: refused at create, naming the
  // attachment, its role and the format the texture has.
  GLuint odd = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &odd);
  glTextureStorage2D(odd, 1, GL_RGB9_E5, 32, 24);
  description.layout.attachments[3] = {retroaa::AttachmentRole::Specular, GL_RGB, odd};
  auto refused = retroaa::Plugin::create(description);
  ASSERT_FALSE(refused);
  expectError(refused.error(), retroaa::ErrorCode::IncompleteFramebuffer, "attachment 3 (Specular, format 0x8c3d)");
  glDeleteTextures(1, &specular);
  glDeleteTextures(1, &odd);
  glDeleteRenderbuffers(1, &depth);
}

TEST(PluginErrors, AShaderLackingAUniformThePluginSetsIsAShaderError) {
  PatchedHost host("default", 32, 24);
  retroaa::ObjectCounter counter;
  std::vector<std::string> warnings;
  retroaa::ShaderLibrary library(counter, "", [&warnings](const std::string& m) { warnings.push_back(m); });
  auto built = library.program("common/fullscreen.vert", "slices/mark_pixels.frag", "", {"uBit"});
  ASSERT_TRUE(built) << built.error().message;
  auto lacking = library.program("common/fullscreen.vert", "slices/mark_pixels.frag", "", {"uBit", "uNotDeclared"});
  ASSERT_FALSE(lacking);
  expectError(lacking.error(), retroaa::ErrorCode::ShaderError, "'uNotDeclared'");
  EXPECT_NE(lacking.error().message.find("slices/mark_pixels.frag"), std::string::npos) << lacking.error().message;
  EXPECT_EQ(counter.live, 1) << "the refused program is deleted";

  // An override that drops a uniform the plugin sets falls back to the built-in, saying which.
  const std::filesystem::path dir =
      writeShaderOverride("retroaa_contract_test", "resolve/resolve.glsl",
                          {{"uniform float uCloseness;", "const float uCloseness = 5.0;"}});
  const app::DisplayImage builtIn = host.render("resolve");
  retroaa::Config config = app::parseMethodSpec("resolve", {}).config;
  config.shaderOverrideDirectory = dir.string();
  ASSERT_TRUE(host.hooks->plugin().reconfigure(config));
  const auto pluginWarnings = host.hooks->plugin().warnings();
  ASSERT_FALSE(pluginWarnings.empty());
  EXPECT_NE(pluginWarnings.back().find("declares no uniform 'uCloseness'"), std::string::npos) << pluginWarnings.back();
  host.renderer->renderFrame(host.scene.camera);
  EXPECT_EQ(app::DisplayImage::fromRgba8(32, 24, host.renderer->readDisplay()).rgb, builtIn.rgb);
  std::filesystem::remove_all(dir);
}

// Texture units are numbered once, in GLSL, and read back when a program is built: the C++ side binds by
// sampler name. Two samplers on one unit, or a sampler bound outside the program (shared_constants.h)
// on another unit than the C++ side binds, refuse the program; an override doing so falls back.
TEST(PluginErrors, SamplersSharingAUnitOrOffTheirSharedUnitAreAShaderError) {
  PatchedHost host("default", 32, 24);
  const std::filesystem::path dir = writeShaderOverride("retroaa_sampler_units_test", "slices/composite.frag",
                                                        {{"layout(binding = 1) uniform usampler2D uSliceCounts;",
                                                          "layout(binding = 0) uniform usampler2D uSliceCounts;"}});
  {
    std::ofstream(dir / "slices" / "mark_pixels.frag")
        << "#version 450 core\nlayout(binding = 1) uniform usampler2D uSliceCounts;\n"
           "layout(binding = 3) uniform sampler2DMS uDepthBuffer;\nuniform int uBit;\nout vec4 outColour;\n"
           "void main() { outColour = vec4(float(texelFetch(uSliceCounts, ivec2(0), 0).x) + "
           "texelFetch(uDepthBuffer, ivec2(0), 0).x + float(uBit)); }\n";
  }
  retroaa::ObjectCounter counter;
  std::vector<std::string> warnings;
  retroaa::ShaderLibrary library(counter, dir.string(), [&warnings](const std::string& m) { warnings.push_back(m); });
  auto composite =
      library.program("common/fullscreen.vert", "slices/composite.frag", "", {"uSliceLight", "uSliceCounts"});
  ASSERT_TRUE(composite) << composite.error().message;  // the built-in one
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("samplers 'uSliceLight' and 'uSliceCounts' share texture unit 0"), std::string::npos)
      << warnings[0];
  EXPECT_EQ(composite.value().unit("uSliceLight"), 0);
  EXPECT_EQ(composite.value().unit("uSliceCounts"), 1);
  auto mark = library.program("common/fullscreen.vert", "slices/mark_pixels.frag", "", {"uBit", "uSliceCounts"});
  ASSERT_TRUE(mark) << mark.error().message;
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[1].find("sampler 'uDepthBuffer' is on texture unit 3, where the plugin binds unit " +
                             std::to_string(retroaa::kUnitDepthStencil)),
            std::string::npos)
      << warnings[1];
  std::filesystem::remove_all(dir);
}

TEST(PluginErrors, AContextBelowGl45IsUnsupported) {
  PatchedHost host("default", 32, 24);
  const EGLDisplay display = eglGetCurrentDisplay();
  const EGLContext previous = eglGetCurrentContext();
  ASSERT_NE(previous, EGL_NO_CONTEXT);
  // An OpenGL ES 3 context: not desktop GL 4.5 core.
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
  const EGLContext es = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  eglBindAPI(EGL_OPENGL_API);
  if (es == EGL_NO_CONTEXT) GTEST_FAIL() << "the EGL display offers no OpenGL ES 3 context to test with";
  ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, es));
  retroaa::Description description = describedHost(host);
  auto created = retroaa::Plugin::create(description);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, previous);
  eglDestroyContext(display, es);
  ASSERT_FALSE(created);
  expectError(created.error(), retroaa::ErrorCode::UnsupportedContext, "needs an OpenGL 4.5 core context");
}

TEST(PluginErrors, AnInconsistentLayoutIsInvalid) {
  PatchedHost host("default", 32, 24);
  retroaa::Description description = describedHost(host);
  description.layout.attachments[1].role = retroaa::AttachmentRole::Other;  // no ViewPosition left
  auto created = retroaa::Plugin::create(description);
  ASSERT_FALSE(created);
  expectError(created.error(), retroaa::ErrorCode::InvalidLayout, "ViewPosition");

  // A velocity attachment must be one of the layout's, holding floats in two channels or more.
  description.layout = patch::describeHostGBuffer(host.renderer->targets());
  description.layout.velocityAttachment = int(description.layout.attachments.size());
  auto missing = retroaa::Plugin::create(description);
  ASSERT_FALSE(missing);
  expectError(missing.error(), retroaa::ErrorCode::InvalidLayout, "velocityAttachment 5 names no attachment");
  description.layout.velocityAttachment = 3;  // the specular target: RGBA8, no floats
  auto unorm = retroaa::Plugin::create(description);
  ASSERT_FALSE(unorm);
  expectError(unorm.error(), retroaa::ErrorCode::InvalidLayout, "must hold floats in at least two channels");
  description.layout.velocityAttachment = 1;  // a float target: accepted (what it holds is the host's word)
  EXPECT_TRUE(retroaa::Plugin::create(description));
}

// A layout without a display target: every method the registry says filters the display is refused
// naming it, every other method runs; a stacked filter is refused on any method.
TEST(PluginErrors, AMethodThatFiltersTheDisplayNeedsADisplayTarget) {
  PatchedHost host("default", 32, 24);
  retroaa::Description description = describedHost(host);
  description.layout.displayFramebuffer = description.layout.displayTexture = 0;
  int filtering = 0;
  for (const retroaa::MethodInfo& row : retroaa::methodTable()) {
    description.config = app::parseMethodSpec(row.name, {}).config;
    auto created = retroaa::Plugin::create(description);
    if (row.filtersDisplay) {
      ++filtering;
      ASSERT_FALSE(created) << row.name;
      expectError(created.error(), retroaa::ErrorCode::InvalidLayout, std::string("method '") + row.name + "'");
    } else {
      EXPECT_TRUE(created) << row.name << ": " << (created ? "" : created.error().message);
    }
  }
  EXPECT_GE(filtering, 5);  // fxaa, smaa, coverage, reconstruct, temporal at least
  description.config = app::parseMethodSpec("resolve+fxaa", {}).config;
  auto stacked = retroaa::Plugin::create(description);
  ASSERT_FALSE(stacked);
  expectError(stacked.error(), retroaa::ErrorCode::InvalidLayout, "method 'resolve' (or a filter stacked on it)");
}

TEST(PluginErrors, DepthEncodingsOutsideTheirDomainAreInvalid) {
  PatchedHost host("default", 32, 24);
  retroaa::Description description = describedHost(host);
  description.layout.depthEncoding.kind = retroaa::DepthEncoding::Kind::FsoCompressedViewZ;
  description.layout.depthEncoding.farDistance = 100000.0f;  // FSO's last segment would divide by 0
  auto created = retroaa::Plugin::create(description);
  ASSERT_FALSE(created);
  expectError(created.error(), retroaa::ErrorCode::InvalidLayout, "farDistance must be above 100000 m");
  description.layout.depthEncoding.kind = retroaa::DepthEncoding::Kind::LogAboveKnee;
  description.layout.depthEncoding.knee = -1.0f;
  created = retroaa::Plugin::create(description);
  ASSERT_FALSE(created);
  expectError(created.error(), retroaa::ErrorCode::InvalidLayout, "knee must be a positive number");
}

// The registry is a table no call can change: built once, read by every plugin, tool and thread.
static_assert(std::is_same_v<decltype(retroaa::techniqueRegistry()), const std::vector<retroaa::TechniqueRow>&>);
