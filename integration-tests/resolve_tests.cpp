// The depth-aware resolve and FXAA through the engine patch, on the demo scenes, against ground truth.
#include <iterator>
#include <map>
#include "commands.h"
#include "test_support.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace testing_support;

namespace {
int countBrighterThanTruth(const app::DisplayImage& image, const app::DisplayImage& truth, float threshold) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += image.luma(x, y) - truth.luma(x, y) > threshold;
  return count;
}
retroaa::Config withSamples(int samples) {
  retroaa::Config config;
  config.samples = samples;
  return config;
}
// `resolve` on the host G-buffer of `frame`.
retroaa::Description resolveDescription(const SyntheticFrame& frame) {
  retroaa::Description description;
  description.config.method = retroaa::Method::Resolve;
  description.layout = patch::describeHostGBuffer(frame.renderer->targets());
  return description;
}
// The plugin of `description`, its w × h MSAA G-buffer filled with `sample` everywhere and resolved
// (null, with a failure, where the description is refused).
std::unique_ptr<retroaa::Plugin> resolveUniform(const retroaa::Description& description, int w, int h,
                                                const SyntheticSample& sample) {
  auto plugin = retroaa::Plugin::create(description);
  if (!plugin) {
    ADD_FAILURE() << plugin.error().message;
    return nullptr;
  }
  fillGeometry(*plugin.value(), w, h, std::vector<std::vector<SyntheticSample>>(size_t(w) * h, {sample}));
  EXPECT_TRUE(plugin.value()->resolve({1.0f}));
  return std::move(plugin.value());
}
}  // namespace

TEST(Resolve, OneSampleEqualsOffExactly) {
  PatchedHost host("default", 160, 120);
  const app::DisplayImage off = host.render("off");
  const app::DisplayImage resolved = host.render("resolve", withSamples(1));
  EXPECT_EQ(host.hooks->plugin().stats().samples, 1);
  EXPECT_EQ(off.rgb, resolved.rgb);
}

TEST(Resolve, MedianDoesNotLightSilhouettesFromBehind) {
  // An orange light sits just behind the hull's left silhouette (the demo scene has the same light).
  // Averaging the G-buffer samples of hull and wall puts a lit point in mid-air near the light.
  PatchedHost host(testDataPath("scenes/light_behind_silhouette.json"), 320, 240);
  const auto truth = app::DisplayImage::fromRgba8(320, 240, host.groundTruth(8).display);
  const int naive = countBrighterThanTruth(host.render("resolve/mean"), truth, 0.12f);
  const int median = countBrighterThanTruth(host.render("resolve"), truth, 0.12f);
  const int off = countBrighterThanTruth(host.render("off"), truth, 0.12f);
  std::printf("pixels brighter than ground truth by > 0.12: naive mean %d, median %d, off %d\n", naive, median, off);
  EXPECT_GT(naive, median + 20);
  EXPECT_LE(median, off + 5);  // the median resolve adds no such pixels over the stock path
}

// Issue 39 #10: on the demo frame the MSAA G-buffer methods' interior PSNR falls below off's, and the
// loss is all on the coplanar plates, the scene's z-fighting hard case. Which plate wins a sample is
// rounding noise: off and the ground truth share the single-sample rasteriser, an MSAA G-buffer
// interpolates depth per sample differently (GL's invariance rules do not span sample counts). Without
// one of the two plates the methods keep off's interior, or better.
TEST(Resolve, KeepsOffsInteriorOnTheDemoFrameOnceNothingZFights) {
  host::Scene scene = host::loadScene("default");
  const size_t objects = scene.objects.size();
  scene.objects.erase(std::remove_if(scene.objects.begin(), scene.objects.end(),
                                     [](const host::Object& o) { return o.name == "plate_blue"; }),
                      scene.objects.end());
  ASSERT_EQ(scene.objects.size(), objects - 1) << "the demo scene's z-fighting plates have moved";
  PatchedHost host(std::move(scene), 320, 240);
  const ScoringTruth truth = host.scoringTruth(8);
  const double off = truth.score(host.render("off")).interiorPsnrDb;
  for (const char* spec : {"resolve", "per-sample"}) {
    const double method = truth.score(host.render(spec)).interiorPsnrDb;
    std::printf("demo frame without plate_blue, interior PSNR: off %.2f dB, %s %.2f dB\n", off, spec, method);
    EXPECT_GE(method, off - 0.02) << spec;
  }
}

TEST(Resolve, ImprovesEdgePsnrOnIntraModelAliasing) {
  PatchedHost host(testDataPath("scenes/intra_model.json"), 240, 180);
  const ScoringTruth truth = host.scoringTruth(8);
  const app::ErrorMetrics off = truth.score(host.render("off"));
  const app::ErrorMetrics resolved = truth.score(host.render("resolve"));
  std::printf("intra-model edge PSNR: off %.2f dB, resolve %.2f dB (%d edge pixels)\n", off.edgePsnrDb,
              resolved.edgePsnrDb, off.edgePixels);
  EXPECT_GT(resolved.edgePsnrDb, off.edgePsnrDb + 1.0);  // stated margin: 1 dB
  EXPECT_GT(resolved.ssim, off.ssim);
}

TEST(Resolve, AnEvenSplitKeepsTheNearerSurfaceWhereTheLayoutLightsIntoFloats) {
  // This host lights into RGBA16F and its ground truth averages radiance: a greeble half covering a pixel
  // dominates it, so resolve_even_split=auto takes the nearer middle, and the neighbourhood's pick is worse.
  PatchedHost host(testDataPath("scenes/intra_model.json"), 160, 120);
  const ScoringTruth truth = host.scoringTruth(4);
  const app::DisplayImage automatic = host.render("resolve");
  const app::DisplayImage nearer = host.render("resolve@resolve_even_split=nearer");
  const app::DisplayImage neighbours = host.render("resolve@resolve_even_split=neighbours");
  EXPECT_EQ(automatic.rgb, nearer.rgb);
  EXPECT_NE(neighbours.rgb, nearer.rgb) << "the scene has pixels split 2 of 4";
  EXPECT_GT(truth.score(nearer).edgePsnrDb, truth.score(neighbours).edgePsnrDb + 1.0);
}

TEST(Resolve, StackedWithFxaaIsNoWorseThanFxaaAlone) {
  PatchedHost host("default", 240, 180);
  const ScoringTruth truth = host.scoringTruth(8);
  const app::ErrorMetrics fxaa = truth.score(host.render("fxaa"));
  const app::ErrorMetrics stacked = truth.score(host.render("resolve+fxaa"));
  const app::ErrorMetrics off = truth.score(host.render("off"));
  std::printf("edge PSNR: off %.2f, fxaa %.2f, resolve+fxaa %.2f dB\n", off.edgePsnrDb, fxaa.edgePsnrDb,
              stacked.edgePsnrDb);
  EXPECT_GT(fxaa.edgePsnrDb, off.edgePsnrDb + 0.5);
  EXPECT_GE(stacked.edgePsnrDb, fxaa.edgePsnrDb - 0.05);
}

TEST(Plugin, AllocatesOnlyWhatTheMethodNeeds) {
  PatchedHost host("default", 64, 48);
  host.render("off");
  EXPECT_EQ(host.hooks->plugin().stats().bytesHeld, 0u);
  EXPECT_EQ(host.hooks->plugin().geometryFramebuffer(), host.renderer->targets().gbufferFramebuffer);
  host.render("fxaa");
  // One RGBA8 copy and a stencil of the pixels FXAA filters, no MSAA.
  EXPECT_EQ(host.hooks->plugin().stats().bytesHeld, 64u * 48u * (4u + 1u));
  host.render("resolve", withSamples(4));
  const int samples = host.hooks->plugin().stats().samples;
  // Five attachments (8+8+8+4+8 bytes) and D24S8 (4 bytes), per sample.
  EXPECT_EQ(host.hooks->plugin().stats().bytesHeld, uint64_t(64 * 48) * samples * 40u);
  EXPECT_NE(host.hooks->plugin().geometryFramebuffer(), host.renderer->targets().gbufferFramebuffer);
  EXPECT_EQ(host.hooks->plugin().waitForStats().evaluationsPerPixel(), 1.0);
}

TEST(Plugin, ClampsSamplesWithAWarningNamingBothCounts) {
  PatchedHost host("default", 32, 24);
  host.render("resolve", withSamples(16));
  const int granted = host.hooks->plugin().stats().samples;
  EXPECT_EQ(granted, context().info().maxSamples);
  const auto warnings = host.hooks->plugin().warnings();
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("samples=16 requested, the context grants " + std::to_string(granted)),
            std::string::npos);
}

TEST(Plugin, Toggling100TimesLeaksNoGlObjectsAndRaisesNoGlError) {
  PatchedHost host("default", 48, 32);
  const int errorsBefore = context().debugErrorCount();
  host.render("off");
  const int objectsAtStart = host.hooks->plugin().stats().glObjectsHeld;
  const char* methods[] = {"resolve", "fxaa", "resolve+fxaa", "resolve/fso", "off"};
  for (int i = 0; i < 100; ++i) {
    retroaa::Config config;
    config.samples = (i % 2) ? 2 : 4;
    config.fxaaQuality = (i % 3) ? retroaa::FxaaQuality::High : retroaa::FxaaQuality::Low;
    host.render(methods[i % 5], config);
    if (i % 25 == 0) host.renderer->resize(48 + i % 7, 32 + i % 5);
  }
  host.render("off");
  EXPECT_EQ(host.hooks->plugin().stats().glObjectsHeld, objectsAtStart);
  EXPECT_EQ(context().debugErrorCount(), errorsBefore);
  EXPECT_TRUE(host.hooks->lastError().empty()) << host.hooks->lastError();
}

TEST(Plugin, SamplersTheHostLeavesBoundChangeNoImage) {
  // A host that keeps sampler objects bound (mipmapped, repeating) on every unit between its draws.
  PatchedHost host("default", 64, 48);
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
  for (const char* method :
       {"resolve+fxaa", "edge", "adaptive", "aggregate", "reconstruct", "smaa", "resolve+coverage"}) {
    glBindSamplers(0, 16, nullptr);
    const app::DisplayImage clean = host.render(method);
    std::vector<GLuint> samplers(16, sampler);
    glBindSamplers(0, 16, samplers.data());
    const app::DisplayImage withSamplers = host.render(method);
    EXPECT_EQ(withSamplers.rgb, clean.rgb) << method;
  }
  glBindSamplers(0, 16, nullptr);
  glDeleteSamplers(1, &sampler);
}

namespace {
// The GL state a host may hold that a plugin call could read or change, read with this test's own list of
// queries (not GlStateSnapshot, which does the restoring): every buffer binding the core profile has a
// target for, per-draw-buffer masks and blending, the texture, sampler and image units the plugin uses,
// the fixed-function state its passes set.
std::map<std::string, std::vector<GLint64>> hostGlState() {
  std::map<std::string, std::vector<GLint64>> state;
  auto integer = [&](const char* name, GLenum query) {
    GLint64 value = 0;
    glGetInteger64v(query, &value);
    state[name].push_back(value);
  };
  auto indexed = [&](const char* name, GLenum query, GLuint count) {
    for (GLuint i = 0; i < count; ++i) {
      GLint64 value = 0;
      glGetInteger64i_v(query, i, &value);
      state[name].push_back(value);
    }
  };
#define READ(q) integer(#q, q)
  READ(GL_ARRAY_BUFFER_BINDING), READ(GL_ELEMENT_ARRAY_BUFFER_BINDING), READ(GL_PIXEL_PACK_BUFFER_BINDING);
  READ(GL_PIXEL_UNPACK_BUFFER_BINDING), READ(GL_QUERY_BUFFER_BINDING), READ(GL_DRAW_INDIRECT_BUFFER_BINDING);
  READ(GL_DISPATCH_INDIRECT_BUFFER_BINDING), READ(GL_COPY_READ_BUFFER_BINDING), READ(GL_COPY_WRITE_BUFFER_BINDING);
  READ(GL_TEXTURE_BUFFER_BINDING), READ(GL_UNIFORM_BUFFER_BINDING), READ(GL_SHADER_STORAGE_BUFFER_BINDING);
  READ(GL_ATOMIC_COUNTER_BUFFER_BINDING), READ(GL_TRANSFORM_FEEDBACK_BUFFER_BINDING);
  READ(GL_DRAW_FRAMEBUFFER_BINDING), READ(GL_READ_FRAMEBUFFER_BINDING), READ(GL_RENDERBUFFER_BINDING);
  READ(GL_CURRENT_PROGRAM), READ(GL_VERTEX_ARRAY_BINDING), READ(GL_ACTIVE_TEXTURE), READ(GL_PROGRAM_PIPELINE_BINDING);
  READ(GL_DEPTH_FUNC), READ(GL_DEPTH_WRITEMASK), READ(GL_STENCIL_FUNC), READ(GL_STENCIL_REF);
  READ(GL_STENCIL_VALUE_MASK), READ(GL_STENCIL_WRITEMASK), READ(GL_STENCIL_FAIL), READ(GL_STENCIL_PASS_DEPTH_PASS);
  READ(GL_STENCIL_BACK_FUNC), READ(GL_STENCIL_BACK_WRITEMASK), READ(GL_CULL_FACE_MODE), READ(GL_FRONT_FACE);
  READ(GL_PACK_ALIGNMENT), READ(GL_UNPACK_ALIGNMENT), READ(GL_PACK_ROW_LENGTH), READ(GL_UNPACK_ROW_LENGTH);
  READ(GL_POLYGON_MODE), READ(GL_PROVOKING_VERTEX), READ(GL_PRIMITIVE_RESTART_INDEX), READ(GL_BLEND_SRC_RGB);
  READ(GL_BLEND_DST_RGB);
#undef READ
  for (GLenum capability :
       {GL_BLEND, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_MULTISAMPLE, GL_SAMPLE_SHADING,
        GL_FRAMEBUFFER_SRGB, GL_RASTERIZER_DISCARD, GL_POLYGON_OFFSET_FILL, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_MASK,
        GL_PRIMITIVE_RESTART, GL_DEPTH_CLAMP, GL_DITHER, GL_COLOR_LOGIC_OP})
    state["enabled " + std::to_string(capability)].push_back(glIsEnabled(capability));
  GLint viewport[4], scissor[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_SCISSOR_BOX, scissor);
  state["viewport"].assign(viewport, viewport + 4);
  state["scissor"].assign(scissor, scissor + 4);
  GLint maxDrawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  for (GLuint i = 0; i < GLuint(std::min(maxDrawBuffers, 8)); ++i) {
    GLboolean mask[4];
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
    state["colour mask " + std::to_string(i)].assign(mask, mask + 4);
    state["blend " + std::to_string(i)].push_back(glIsEnabledi(GL_BLEND, i));
    for (GLenum query : {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                         GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA}) {
      GLint value = 0;
      glGetIntegeri_v(query, i, &value);
      state["blend function " + std::to_string(i)].push_back(value);
    }
  }
  indexed("uniform buffers", GL_UNIFORM_BUFFER_BINDING, 4);
  indexed("storage buffers", GL_SHADER_STORAGE_BUFFER_BINDING, 4);
  indexed("atomic counter buffers", GL_ATOMIC_COUNTER_BUFFER_BINDING, 1);
  indexed("atomic counter ranges", GL_ATOMIC_COUNTER_BUFFER_START, 1);
  indexed("atomic counter ranges", GL_ATOMIC_COUNTER_BUFFER_SIZE, 1);
  indexed("uniform buffer ranges", GL_UNIFORM_BUFFER_START, 4);
  indexed("uniform buffer ranges", GL_UNIFORM_BUFFER_SIZE, 4);
  indexed("image units", GL_IMAGE_BINDING_NAME, 8);
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (int unit = 0; unit < 16; ++unit) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    for (GLenum binding : {GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_2D_MULTISAMPLE, GL_SAMPLER_BINDING}) {
      GLint value = 0;
      glGetIntegerv(binding, &value);
      state["unit " + std::to_string(unit)].push_back(value);
    }
  }
  glActiveTexture(GLenum(active));
  return state;
}

std::string differences(const std::map<std::string, std::vector<GLint64>>& before,
                        const std::map<std::string, std::vector<GLint64>>& after) {
  std::string out;
  for (const auto& [name, values] : before)
    if (after.at(name) != values) out += name + "; ";
  return out;
}
}  // namespace

// The promise of plugin.h ("every call restores the GL state it changed"), checked from outside: unusual host
// state on every buffer target (pixel pack and unpack, query and indirect buffers among them) and per draw
// buffer, then every public call of several methods and stacks, forward passes included.
TEST(Plugin, EveryPublicCallLeavesTheHostsGlStateAsItsOwnQueriesReadIt) {
  PatchedHost host("default", 64, 48);
  host.render("off");
  retroaa::Plugin& plugin = host.hooks->plugin();
  const host::HostTargets& targets = host.renderer->targets();
  retroaa::GBufferLayout layout = patch::describeHostGBuffer(targets);
  layout.drawsForwardPasses = true;
  GLuint buffers[12] = {};  // one per plain target, then the host's atomic counter, storage and uniform buffers
  glCreateBuffers(12, buffers);
  for (GLuint buffer : buffers) glNamedBufferStorage(buffer, 1 << 20, nullptr, GL_DYNAMIC_STORAGE_BIT);
  const GLenum targetsToBind[] = {GL_PIXEL_PACK_BUFFER,
                                  GL_PIXEL_UNPACK_BUFFER,
                                  GL_QUERY_BUFFER,
                                  GL_DRAW_INDIRECT_BUFFER,
                                  GL_DISPATCH_INDIRECT_BUFFER,
                                  GL_COPY_READ_BUFFER,
                                  GL_COPY_WRITE_BUFFER,
                                  GL_ARRAY_BUFFER,
                                  GL_TEXTURE_BUFFER};
  for (size_t i = 0; i < std::size(targetsToBind); ++i) glBindBuffer(targetsToBind[i], buffers[i]);
  glColorMaski(1, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glEnablei(GL_BLEND, 2);
  glBlendFuncSeparatei(3, GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBlendEquationi(4, GL_MAX);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  glEnable(GL_POLYGON_OFFSET_FILL);
  // Unusual host state, as a state-caching engine might leave it; the host's current program stays current.
  glViewport(3, 4, 20, 10);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 2, 3, 4);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 3, 0x0F);
  glDepthFunc(GL_GEQUAL);
  glBindTextureUnit(0, targets.color);
  glBindTextureUnit(7, targets.normal);
  glActiveTexture(GL_TEXTURE5);
  glBindImageTexture(3, targets.color, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA16F);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glBindBufferRange(GL_ATOMIC_COUNTER_BUFFER, 0, buffers[9], 256, 512);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[10]);
  glBindBufferRange(GL_UNIFORM_BUFFER, 1, buffers[11], 0, 256);
  const auto before = hostGlState();
  const int errorsBefore = context().debugErrorCount();
  auto expectUnchanged = [&](const std::string& call) {
    EXPECT_EQ(differences(before, hostGlState()), "") << "changed by " << call;
    EXPECT_EQ(context().debugErrorCount(), errorsBefore) << "a GL error in " << call;
  };
  std::vector<uint8_t> countsWithoutPackBuffer;
  for (const char* spec :
       {"edge", "per-sample", "adaptive", "aggregate", "smaa-s2x", "resolve+fxaa@resolve_compute=on", "resolve+smaa",
        "reconstruct", "coverage", "temporal", "edge+temporal", "resolve+reconstruct@reconstruct_compute=on"}) {
    retroaa::Config config;
    ASSERT_TRUE(retroaa::applyMethodSpec(config, spec));
    config.measureGpuTime = true;
    ASSERT_TRUE(plugin.reconfigure(config));
    expectUnchanged(std::string(spec) + ": reconfigure");
    ASSERT_TRUE(plugin.resize(layout));
    expectUnchanged(std::string(spec) + ": resize");
    for (int frame = 0; frame < 2; ++frame) {
      ASSERT_TRUE(plugin.resolve(retroaa::FrameInfo{}));
      expectUnchanged(std::string(spec) + ": resolve");
      ASSERT_TRUE(plugin.shade([](retroaa::GLuintHandle target) { glBindFramebuffer(GL_FRAMEBUFFER, target); }));
      expectUnchanged(std::string(spec) + ": shade");
      auto forward = plugin.beginForward();
      ASSERT_TRUE(forward) << spec;
      expectUnchanged(std::string(spec) + ": beginForward");
      ASSERT_TRUE(plugin.endForward());
      expectUnchanged(std::string(spec) + ": endForward");
      ASSERT_TRUE(plugin.post());
      expectUnchanged(std::string(spec) + ": post");
    }
    plugin.stats();
    expectUnchanged(std::string(spec) + ": stats");
    plugin.waitForStats();
    expectUnchanged(std::string(spec) + ": waitForStats");
    // A readback with the host's pixel pack buffer bound reaches the caller's memory, not the buffer.
    const std::vector<uint8_t> counts = plugin.readSliceCounts();
    expectUnchanged(std::string(spec) + ": readSliceCounts");
    if (std::string(spec) == "per-sample") {
      EXPECT_EQ(std::count(counts.begin(), counts.end(), uint8_t(4)), std::ptrdiff_t(counts.size()))
          << "per-sample counts every sample everywhere";
    }
  }
  {
    retroaa::Description description;
    description.layout = layout;
    ASSERT_TRUE(retroaa::applyMethodSpec(description.config, "edge+temporal"));
    auto created = retroaa::Plugin::create(description);
    ASSERT_TRUE(created);
    expectUnchanged("create");
  }
  expectUnchanged("the plugin's destruction");
  retroaa::Config off;
  ASSERT_TRUE(plugin.reconfigure(off));
  ASSERT_TRUE(plugin.resize(patch::describeHostGBuffer(targets)));
  for (GLenum target : targetsToBind) glBindBuffer(target, 0);
  glDeleteBuffers(12, buffers);  // unbinds them everywhere
  glBindImageTexture(3, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA16F);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(7, 0);
  glActiveTexture(GL_TEXTURE0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisablei(GL_BLEND, 2);
  glBlendFuncSeparatei(3, GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
  glBlendEquationi(4, GL_FUNC_ADD);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

TEST(Plugin, BrokenShaderOverrideFallsBackToTheBuiltInAndSaysWhere) {
  const auto dir = std::filesystem::temp_directory_path() / "retroaa_override_test";
  std::filesystem::create_directories(dir / "resolve");
  std::ofstream(dir / "resolve" / "resolve.frag") << "#version 450 core\nvoid main() {\n  this is not glsl;\n}\n";
  PatchedHost host("default", 64, 48);
  const app::DisplayImage builtIn = host.render("resolve");
  retroaa::Config config;
  config.shaderOverrideDirectory = dir.string();
  const app::DisplayImage overridden = host.render("resolve", config);
  EXPECT_EQ(builtIn.rgb, overridden.rgb);
  const auto warnings = host.hooks->plugin().warnings();
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("resolve/resolve.frag does not compile"), std::string::npos) << warnings.back();
  EXPECT_NE(warnings.back().find("0:"), std::string::npos) << "the compiler's line is missing: " << warnings.back();
}

TEST(Plugin, AHostDrawsIntoAMultisampledAttachmentBeforeResolve) {
  // Decals: the host writes the MSAA albedo through a framebuffer of its own between the model pass and
  // resolve(); the resolved G-buffer carries it.
  constexpr int w = 8, h = 4;
  SyntheticFrame frame(w, h);
  auto hooks = frame.attach(retroaa::Method::Resolve);
  ASSERT_TRUE(hooks);
  retroaa::Plugin& plugin = hooks->plugin();
  fillGeometry(plugin, w, h, std::vector<std::vector<SyntheticSample>>(w * h, {surfaceSample(10)}));
  const GLuint albedo = plugin.multisampledAttachment(retroaa::AttachmentRole::Albedo);
  ASSERT_NE(albedo, 0u);
  GLint samples = 0;
  glGetTextureLevelParameteriv(albedo, 0, GL_TEXTURE_SAMPLES, &samples);
  EXPECT_EQ(samples, plugin.stats().samples);
  GLuint decal = 0;
  glCreateFramebuffers(1, &decal);
  glNamedFramebufferTexture(decal, GL_COLOR_ATTACHMENT0, albedo, 0);
  const float paint[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glClearNamedFramebufferfv(decal, GL_COLOR, 0, paint);
  glDeleteFramebuffers(1, &decal);
  ASSERT_TRUE(plugin.resolve({1.0f}));
  for (const glm::vec4& c : frame.read(frame.renderer->targets().color))
    ASSERT_EQ(c, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  // Without an MSAA G-buffer there is none to hand out.
  retroaa::Config fxaa;
  fxaa.method = retroaa::Method::Fxaa;
  ASSERT_TRUE(plugin.reconfigure(fxaa));
  EXPECT_EQ(plugin.multisampledAttachment(retroaa::AttachmentRole::Albedo), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Plugin, AcceptsEveryCommonDepthFormatAndRefusesWhatIsNoDepth) {
  // The MSAA depth takes the host's format, and the resolve writes the host's depth texture, whatever
  // its format: sized or unsized, with or without stencil.
  constexpr int w = 8, h = 4;
  struct Format {
    const char* name;
    GLenum internal, unsizedFormat, unsizedType;  // unsizedFormat != 0: allocate with glTexImage2D
    double tolerance;
  };
  const Format formats[] = {{"GL_DEPTH24_STENCIL8", GL_DEPTH24_STENCIL8, 0, 0, 1e-6},
                            {"GL_DEPTH_COMPONENT32F", GL_DEPTH_COMPONENT32F, 0, 0, 0},
                            {"GL_DEPTH32F_STENCIL8", GL_DEPTH32F_STENCIL8, 0, 0, 0},
                            {"GL_DEPTH_COMPONENT16", GL_DEPTH_COMPONENT16, 0, 0, 2e-5},
                            {"unsized GL_DEPTH_COMPONENT", GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_FLOAT, 1e-6}};
  const SyntheticSample sample = surfaceSample(10);
  for (const Format& format : formats)
    for (const bool compute : {false, true}) {  // resolve_compute: its depth reaches the host through a copy pass
      SyntheticFrame frame(w, h);
      retroaa::Description description = resolveDescription(frame);
      description.config.resolveCompute = compute;
      GLuint depth = 0;
      if (format.unsizedFormat) {
        glGenTextures(1, &depth);
        glBindTexture(GL_TEXTURE_2D, depth);
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(format.internal), w, h, 0, format.unsizedFormat, format.unsizedType,
                     nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
      } else {
        glCreateTextures(GL_TEXTURE_2D, 1, &depth);
        glTextureStorage2D(depth, 1, format.internal, w, h);
      }
      description.layout.depthStencilTexture = depth;
      {
        const std::unique_ptr<retroaa::Plugin> plugin = resolveUniform(description, w, h, sample);
        ASSERT_TRUE(plugin) << format.name;
        EXPECT_TRUE(plugin->warnings().empty()) << plugin->warnings().front();
      }
      std::vector<float> values(w * h);
      glGetTextureImage(depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(values.size() * sizeof(float)), values.data());
      // Float formats keep the sample's depth exactly: the MSAA depth is float too.
      for (float v : values)
        ASSERT_NEAR(v, sample.depthBuffer.x, format.tolerance) << format.name << " compute " << compute;
      glDeleteTextures(1, &depth);
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << format.name;
    }
  // A colour texture as depth: InvalidLayout naming the field.
  SyntheticFrame frame(w, h);
  retroaa::Description description;
  description.layout = patch::describeHostGBuffer(frame.renderer->targets());
  description.layout.depthStencilTexture = frame.renderer->targets().color;
  auto refused = retroaa::Plugin::create(description);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().code, retroaa::ErrorCode::InvalidLayout);
  EXPECT_NE(refused.error().message.find("depthStencilTexture"), std::string::npos) << refused.error().message;
}

TEST(Plugin, AComputeResolveOfAnAttachmentWithoutImageStoresFallsBackAndSaysWhich) {
  // The host's specular attachment as RGB16F, a format image stores cannot write: resolve_compute=on
  // warns naming the attachment and resolves through the full-screen pass, which writes it.
  constexpr int w = 8, h = 4;
  SyntheticFrame frame(w, h);
  retroaa::Description description = resolveDescription(frame);
  description.config.resolveCompute = true;
  GLuint specular = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &specular);
  glTextureStorage2D(specular, 1, GL_RGB16F, w, h);
  description.layout.attachments[3].texture = specular;
  description.layout.attachments[3].internalFormat = GL_RGB16F;
  SyntheticSample sample = surfaceSample(10);
  sample.attachments[3] = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
  {
    const std::unique_ptr<retroaa::Plugin> plugin = resolveUniform(description, w, h, sample);
    ASSERT_TRUE(plugin);
    const std::vector<std::string> warnings = plugin->warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0],
              "resolve_compute=on: attachment 3's format takes no image stores; using the full-screen pass");
  }
  std::vector<glm::vec3> values(w * h);
  glGetTextureImage(specular, 0, GL_RGB, GL_FLOAT, GLsizei(values.size() * sizeof(glm::vec3)), values.data());
  for (const glm::vec3& v : values) EXPECT_EQ(v, glm::vec3(0.25f, 0.5f, 0.75f));
  glDeleteTextures(1, &specular);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Plugin, ALayoutWhoseDataLooksWrongIsNamedInAWarning) {
  // The first frame counts, with occlusion queries read a frame later (never waited on), the pixels
  // without geometry and those with geometry at view depth <= 0 under the layout's description.
  constexpr int w = 16, h = 8;
  SyntheticSample worldSpace = surfaceSample(10);
  worldSpace.attachments[1].z = -4.0f;  // a world-space z labelled as view depth
  const std::pair<const char*, SyntheticSample> cases[] = {
      {"view depth <= 0", worldSpace}, {"no sample with geometry", backgroundSample()}, {nullptr, surfaceSample(10)}};
  for (const auto& [expected, sample] : cases) {
    SyntheticFrame frame(w, h);
    auto hooks = frame.attach(retroaa::Method::Resolve);
    ASSERT_TRUE(hooks);
    retroaa::Plugin& plugin = hooks->plugin();
    for (int f = 0; f < 2; ++f) {
      fillGeometry(plugin, w, h, std::vector<std::vector<SyntheticSample>>(w * h, {sample}));
      ASSERT_TRUE(plugin.resolve({1.0f}));
      glFinish();  // the test's own wait, so that frame 2 finds the counts available
    }
    std::string layoutWarnings;
    for (const std::string& warning : plugin.warnings())
      if (warning.rfind("layout check:", 0) == 0) layoutWarnings += warning + "\n";
    if (expected) {
      EXPECT_NE(layoutWarnings.find(expected), std::string::npos) << layoutWarnings;
      EXPECT_NE(layoutWarnings.find("depthChannel=2"), std::string::npos) << layoutWarnings;
    } else {
      EXPECT_EQ(layoutWarnings, "") << "a plausible frame";
    }
  }
}

TEST(Plugin, TakesADepthRenderbufferThroughATextureMirror) {
  // A host whose depth is a renderbuffer: the plugin mirrors it in a texture of the same format, writes
  // the resolved depth back into it after resolve(), and holds the mirror's bytes on top.
  constexpr int w = 8, h = 4;
  const SyntheticSample sample = surfaceSample(10);
  SyntheticFrame frame(w, h);
  GLuint renderbuffer = 0, readBack = 0;
  glCreateRenderbuffers(1, &renderbuffer);
  glNamedRenderbufferStorage(renderbuffer, GL_DEPTH24_STENCIL8, w, h);
  retroaa::Description description = resolveDescription(frame);
  const uint64_t bytesWithTexture = retroaa::Plugin::create(description).value()->stats().bytesHeld;
  description.layout.depthStencilTexture = 0;
  description.layout.depthStencilRenderbuffer = renderbuffer;
  {
    const std::unique_ptr<retroaa::Plugin> plugin = resolveUniform(description, w, h, sample);
    ASSERT_TRUE(plugin);
    EXPECT_EQ(plugin->stats().bytesHeld, bytesWithTexture + uint64_t(w) * h * 4);
    // `off` holds nothing, the mirror neither; a method that reads depth again takes a new one.
    ASSERT_TRUE(plugin->reconfigure(retroaa::Config{}));
    EXPECT_EQ(plugin->stats().bytesHeld, 0u);
    ASSERT_TRUE(plugin->reconfigure(app::parseMethodSpec("fxaa", {}).config));  // post() reads it back
    EXPECT_GT(plugin->stats().bytesHeld, 0u);
    ASSERT_TRUE(plugin->post());
  }
  glCreateFramebuffers(1, &readBack);
  glNamedFramebufferRenderbuffer(readBack, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffer);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, readBack);
  std::vector<float> values(w * h);
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, values.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  for (float v : values) ASSERT_NEAR(v, sample.depthBuffer.x, 1e-6);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  // Both names, or a renderbuffer without depth: InvalidLayout naming the field.
  description.layout.depthStencilTexture = frame.renderer->targets().depthStencil;
  auto both = retroaa::Plugin::create(description);
  ASSERT_FALSE(both);
  EXPECT_NE(both.error().message.find("depthStencilRenderbuffer"), std::string::npos) << both.error().message;
  GLuint colour = 0;
  glCreateRenderbuffers(1, &colour);
  glNamedRenderbufferStorage(colour, GL_RGBA8, w, h);
  description.layout.depthStencilTexture = 0;
  description.layout.depthStencilRenderbuffer = colour;
  auto noDepth = retroaa::Plugin::create(description);
  ASSERT_FALSE(noDepth);
  EXPECT_EQ(noDepth.error().code, retroaa::ErrorCode::InvalidLayout);
  EXPECT_NE(noDepth.error().message.find("depthStencilRenderbuffer"), std::string::npos) << noDepth.error().message;
  glDeleteRenderbuffers(1, &colour);
  glDeleteRenderbuffers(1, &renderbuffer);
  glDeleteFramebuffers(1, &readBack);
}
