// What a foreign engine's layout asks of the plugin, on a miniature host shaped like SuperTuxKart's
// deferred renderer: albedo and a spheremap-encoded normal in two RGBA8 targets (roughness and
// metallic in the normal's b and a), positions from a D24S8 depth only, and a lighting pass that writes
// diffuse and specular apart into two R11F_G11F_B10F targets (GBufferLayout::extraLightTextures).
#include "gl_objects.h"
#include "test_support.h"

#include <glm/glm.hpp>

#include <cmath>

using testing_support::drawWithFragment;

namespace {

constexpr int kWidth = 24, kHeight = 16;
// The two surfaces either side of a sloped edge: albedo and (unit) normal.
const glm::vec3 kAlbedoA(0.9f, 0.2f, 0.1f), kAlbedoB(0.1f, 0.3f, 0.8f);
const glm::vec3 kNormalA = glm::normalize(glm::vec3(0.6f, 0.3f, 0.7f)),
                kNormalB = glm::normalize(glm::vec3(-0.5f, 0.2f, 0.4f));
const glm::vec3 kToLight = glm::normalize(glm::vec3(0.2f, 0.4f, 1.0f));

// The shared GLSL: which surface a point of the screen is on (x + 0.37·y < 10.3: surface A), STK's own
// normal encoding (data/shaders/utils/encode_normal.frag and decodeNormal.frag, verbatim), and the
// test lighting: diffuse = albedo · max(n·l, 0), specular = half of it.
const char* kShared = R"(
vec2 EncodeNormal(vec3 n) { return normalize(n.xy) * sqrt(n.z * 0.5 + 0.5); }
vec3 DecodeNormal(vec2 n) {
  float z = dot(n, n) * 2. - 1.;
  vec2 xy = normalize(n) * sqrt(1. - z * z);
  return vec3(xy, z);
}
bool onA(vec2 p) { return p.x + 0.37 * p.y < 10.3; }
)";

struct MiniatureStk {
  host::Texture albedo = host::makeTexture2D(GL_RGBA8, kWidth, kHeight, "mini.albedo");
  host::Texture normal = host::makeTexture2D(GL_RGBA8, kWidth, kHeight, "mini.normal");
  host::Texture depth = host::makeTexture2D(GL_DEPTH24_STENCIL8, kWidth, kHeight, "mini.depth");
  host::Texture diffuse = host::makeTexture2D(GL_R11F_G11F_B10F, kWidth, kHeight, "mini.diffuse");
  host::Texture specular = host::makeTexture2D(GL_R11F_G11F_B10F, kWidth, kHeight, "mini.specular");
  host::Texture display = host::makeTexture2D(GL_RGBA8, kWidth, kHeight, "mini.display");
  GLuint gbuffer = 0, light = 0, displayTarget = 0;
  float curvature = 0;  // surface A's normal turns by this (in x) per pixel: a curved surface
  retroaa::DepthBufferEncoding depthEncoding = retroaa::DepthBufferEncoding::Perspective;

  MiniatureStk() {
    glCreateFramebuffers(1, &gbuffer);
    glNamedFramebufferTexture(gbuffer, GL_COLOR_ATTACHMENT0, albedo, 0);
    glNamedFramebufferTexture(gbuffer, GL_COLOR_ATTACHMENT1, normal, 0);
    glNamedFramebufferTexture(gbuffer, GL_DEPTH_STENCIL_ATTACHMENT, depth, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(gbuffer, 2, buffers);
    glCreateFramebuffers(1, &light);
    glNamedFramebufferTexture(light, GL_COLOR_ATTACHMENT0, diffuse, 0);
    glNamedFramebufferTexture(light, GL_COLOR_ATTACHMENT1, specular, 0);
    glNamedFramebufferDrawBuffers(light, 2, buffers);
    glCreateFramebuffers(1, &displayTarget);
    glNamedFramebufferTexture(displayTarget, GL_COLOR_ATTACHMENT0, display, 0);
  }
  ~MiniatureStk() {
    glDeleteFramebuffers(1, &gbuffer);
    glDeleteFramebuffers(1, &light);
    glDeleteFramebuffers(1, &displayTarget);
  }

  retroaa::GBufferLayout layout() const {
    retroaa::GBufferLayout layout;
    layout.width = kWidth;
    layout.height = kHeight;
    layout.attachments = {{retroaa::AttachmentRole::Albedo, GL_RGBA8, albedo},
                          {retroaa::AttachmentRole::NormalGloss, GL_RGBA8, normal}};
    layout.normalEncoding = retroaa::NormalEncoding::Spheremap;
    layout.depthSource = retroaa::DepthSource::DepthBuffer;
    layout.depthBufferEncoding = depthEncoding;
    layout.gbufferFramebuffer = gbuffer;
    layout.depthStencilTexture = depth;
    layout.lightFramebuffer = light;
    layout.lightTexture = diffuse;
    layout.extraLightTextures = {specular};
    layout.displayFramebuffer = displayTarget;
    layout.displayTexture = display;
    return layout;
  }

  // The solid pass: every sample of the plugin's geometry framebuffer, surface A or B by where the
  // sample lies, normals stored as STK stores them (0.5·EncodeNormal(n) + 0.5, b roughness, a metallic).
  void solidPass(GLuint target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, kWidth, kHeight);
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    const std::string source = std::string("#version 450 core\n") + kShared + R"(
uniform vec3 uAlbedoA, uAlbedoB, uNormalA, uNormalB;
uniform float uCurvature;
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
void main() {
  bool a = onA(floor(gl_FragCoord.xy) + gl_SamplePosition);  // reading it runs this once per sample
  outAlbedo = vec4(a ? uAlbedoA : uAlbedoB, 0.0);
  vec3 normalA = normalize(uNormalA + vec3(uCurvature * floor(gl_FragCoord.x), 0.0, 0.0));
  outNormal = vec4(0.5 * EncodeNormal(a ? normalA : uNormalB) + 0.5, 0.25, 0.75);
  gl_FragDepth = a ? 0.9 : 0.99;
})";
    drawWithFragment(source.c_str(), [this](GLuint p) {
      glProgramUniform1f(p, glGetUniformLocation(p, "uCurvature"), curvature);
      glProgramUniform3fv(p, glGetUniformLocation(p, "uAlbedoA"), 1, &kAlbedoA.x);
      glProgramUniform3fv(p, glGetUniformLocation(p, "uAlbedoB"), 1, &kAlbedoB.x);
      glProgramUniform3fv(p, glGetUniformLocation(p, "uNormalA"), 1, &kNormalA.x);
      glProgramUniform3fv(p, glGetUniformLocation(p, "uNormalB"), 1, &kNormalB.x);
    });
    glDisable(GL_DEPTH_TEST);
  }

  // STK-style lighting: reads its G-buffer through the textures, writes diffuse and specular apart.
  void lighting(GLuint target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, kWidth, kHeight);
    glBindTextureUnit(0, albedo);
    glBindTextureUnit(1, normal);
    const std::string source = std::string("#version 450 core\n") + kShared + R"(
layout(binding = 0) uniform sampler2D uAlbedo;
layout(binding = 1) uniform sampler2D uNormal;
uniform vec3 uToLight;
layout(location = 0) out vec4 outDiffuse;
layout(location = 1) out vec4 outSpecular;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 n = normalize(DecodeNormal(2.0 * texelFetch(uNormal, pixel, 0).xy - 1.0));
  vec3 diffuse = texelFetch(uAlbedo, pixel, 0).rgb * max(dot(n, uToLight), 0.0);
  outDiffuse = vec4(diffuse, 1.0);
  outSpecular = vec4(0.5 * diffuse, 1.0);
})";
    drawWithFragment(source.c_str(),
                     [](GLuint p) { glProgramUniform3fv(p, glGetUniformLocation(p, "uToLight"), 1, &kToLight.x); });
  }

  std::vector<glm::vec4> read(GLuint texture) const {
    std::vector<glm::vec4> pixels(size_t(kWidth) * kHeight);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(glm::vec4)), pixels.data());
    return pixels;
  }
};

std::unique_ptr<retroaa::Plugin> createPlugin(const MiniatureStk& host, const std::string& spec) {
  retroaa::Description description;
  EXPECT_TRUE(retroaa::applyMethodSpec(description.config, spec)) << spec;
  description.layout = host.layout();
  auto plugin = retroaa::Plugin::create(description);
  EXPECT_TRUE(plugin) << (plugin ? "" : plugin.error().message);
  return plugin ? std::move(plugin.value()) : nullptr;
}

void runFrame(MiniatureStk& host, retroaa::Plugin& plugin) {
  host.solidPass(plugin.geometryFramebuffer());
  ASSERT_TRUE(plugin.resolve({1.396f, 1.0f, 1200.0f}));                             // SuperTuxKart's planes
  if (const GLuint prepass = plugin.prepassFramebuffer()) host.solidPass(prepass);  // coverage, reconstruct
  ASSERT_TRUE(plugin.shade([&](GLuint target) { host.lighting(target); }));
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

glm::vec3 litSurface(bool a) {
  return (a ? kAlbedoA : kAlbedoB) * std::max(glm::dot(a ? kNormalA : kNormalB, kToLight), 0.0f);
}

}  // namespace

TEST(ForeignLayout, PerSampleLightsEverySampleAndCompositesBothLightOutputs) {
  testing_support::context();
  MiniatureStk host;
  auto plugin = createPlugin(host, "per-sample@samples=4");
  ASSERT_TRUE(plugin);
  runFrame(host, *plugin);
  // Where the driver puts the samples of the plugin's MSAA G-buffer, to light them here too.
  std::vector<float> positions;
  glBindFramebuffer(GL_FRAMEBUFFER, plugin->geometryFramebuffer());
  for (int s = 0; s < plugin->stats().samples; ++s) {
    float xy[2];
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(s), xy);
    positions.push_back(xy[0]);
    positions.push_back(xy[1]);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const auto diffuse = host.read(host.diffuse), specular = host.read(host.specular);
  int edgePixels = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      glm::vec3 expected(0.0f);
      int onA = 0;
      const int samples = int(positions.size() / 2);
      for (int s = 0; s < samples; ++s) {
        const bool a = x + positions[2 * s] + 0.37f * (y + positions[2 * s + 1]) < 10.3f;
        onA += a;
        expected += litSurface(a) / float(samples);
      }
      edgePixels += onA > 0 && onA < samples;
      const glm::vec3 d(diffuse[size_t(y) * kWidth + x]), sp(specular[size_t(y) * kWidth + x]);
      // R11F_G11F_B10F keeps 5-6 mantissa bits; the normals went through 8-bit spheremap storage.
      EXPECT_NEAR(d.r, expected.r, 0.03f) << x << "," << y;
      EXPECT_NEAR(d.g, expected.g, 0.03f) << x << "," << y;
      EXPECT_NEAR(d.b, expected.b, 0.03f) << x << "," << y;
      // The specular output went through the same slices and weights: half the diffuse.
      EXPECT_NEAR(sp.r, 0.5f * d.r, 0.02f) << x << "," << y;
      EXPECT_NEAR(sp.b, 0.5f * d.b, 0.02f) << x << "," << y;
    }
  EXPECT_GT(edgePixels, kHeight / 2) << "the edge crosses every row: its pixels mix both surfaces";
}

TEST(ForeignLayout, TheResolveKeepsASpheremapNormalThroughDecodeAndReencode) {
  testing_support::context();
  MiniatureStk host;
  for (const char* spec : {"resolve", "resolve/fso", "edge", "aggregate"}) {
    auto plugin = createPlugin(host, std::string(spec) + "@samples=4");
    ASSERT_TRUE(plugin);
    runFrame(host, *plugin);
    const auto diffuse = host.read(host.diffuse);
    const auto normals = host.read(host.normal);
    std::vector<float> depth(size_t(kWidth) * kHeight);
    glGetTextureImage(host.depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)), depth.data());
    // Away from the edge every sample is one surface: the averaged normal is that surface's, the light
    // its light, and the roughness and metallic channels pass through.
    for (int y = 0; y < kHeight; ++y)
      for (const int x : {0, 1, kWidth - 2, kWidth - 1}) {
        const bool a = x + 0.37f * y < 10.3f - 1.5f;
        if (!a && x + 0.37f * y < 10.3f + 1.5f) continue;
        const glm::vec3 expected = litSurface(a), got(diffuse[size_t(y) * kWidth + x]);
        EXPECT_LT(glm::length(got - expected), 0.03f) << spec << " at " << x << "," << y;
        // The host's depth holds the surface's, for its lighting to rebuild positions from.
        EXPECT_NEAR(depth[size_t(y) * kWidth + x], a ? 0.9f : 0.99f, 1e-5f) << spec << " at " << x << "," << y;
        EXPECT_NEAR(normals[size_t(y) * kWidth + x].z, 0.25f, 1.0f / 255) << spec;
        EXPECT_NEAR(normals[size_t(y) * kWidth + x].w, 0.75f, 1.0f / 255) << spec;
      }
  }
}

// SuperTuxKart's depth holds stencil bits, and the slices write their samples' depth into it: after
// shade() it holds the resolved depth again, bit for bit, and the stencil is the host's. The restore
// writes the kept attachments back and the depth from the floats the resolve wrote beside it, in one
// draw, rather than resolving the whole G-buffer again, and never copies the depth-stencil back over the
// stencil.
TEST(ForeignLayout, AfterShadeTheDepthIsTheResolvedOneAndTheStencilTheHosts) {
  testing_support::context();
  auto depthStencilBits = [](GLuint texture) {
    std::vector<uint32_t> bits(size_t(kWidth) * kHeight);
    glGetTextureImage(texture, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, GLsizei(bits.size() * 4), bits.data());
    return bits;
  };
  for (const char* spec :
       {"edge@samples=4@measure_gpu_time=on@measure_pass_floors=on",
        "per-sample@samples=4@measure_gpu_time=on@measure_pass_floors=on",
        "aggregate@samples=4@measure_gpu_time=on@measure_pass_floors=on"}) {  // the passes listed, with floors
    MiniatureStk host;
    auto plugin = createPlugin(host, spec);
    ASSERT_TRUE(plugin);
    host.solidPass(plugin->geometryFramebuffer());
    ASSERT_TRUE(plugin->resolve({1.396f, 1.0f, 1200.0f}));
    const GLint hostStencil = 0x5A;
    glClearNamedFramebufferiv(host.gbuffer, GL_STENCIL, 0, &hostStencil);  // the host's own marks
    const std::vector<uint32_t> resolved = depthStencilBits(host.depth);
    ASSERT_TRUE(plugin->shade([&](GLuint target) { host.lighting(target); }));
    EXPECT_EQ(depthStencilBits(host.depth), resolved) << spec;
    EXPECT_EQ(resolved[0] & 0xFFu, 0x5Au) << spec;
    const retroaa::Stats stats = plugin->waitForStats();
    bool kept = false;
    const retroaa::PassStats *resolve = nullptr, *resolveFloor = nullptr, *restore = nullptr, *restoreFloor = nullptr;
    for (const retroaa::PassStats& pass : stats.passes) {
      kept = kept || pass.name == "resolve.keep";
      if (pass.name == "resolve") resolve = &pass;
      if (pass.name == "resolve.floor") resolveFloor = &pass;
      if (pass.name == "resolve.restore") restore = &pass;
      if (pass.name == "resolve.restore.floor") restoreFloor = &pass;
    }
    EXPECT_TRUE(kept) << spec << ": the attachments copied before the slices, not resolved again after them";
    // The traffic the resolve states counts the depth floats it writes, as its floor (its real targets) does.
    ASSERT_TRUE(resolve && resolveFloor) << spec;
    EXPECT_EQ(resolveFloor->minimumBytes,
              resolveFloor->fragmentInvocations * (resolve->minimumBytes / (uint64_t(kWidth) * kHeight)))
        << spec;
    // The restore is one draw that moves the two RGBA8 attachments (read from the kept copies, written to
    // the host's) as well as the depth: a copy per attachment is no draw, and a floor that replays draws
    // would see the depth alone (8 B a pixel). It draws where the slices wrote: every pixel, or the tiles
    // of the pixels lit more than once.
    ASSERT_TRUE(restoreFloor && restore) << spec;
    std::printf("%s: restore %llu invocations, resolve %llu\n", spec, (unsigned long long)restore->fragmentInvocations,
                (unsigned long long)resolve->fragmentInvocations);
    EXPECT_EQ(restoreFloor->fragmentInvocations, restore->fragmentInvocations) << spec;
    if (std::string(spec).rfind("edge", 0) == 0)  // its slice 0 writes only where count > 1
      EXPECT_LT(restore->fragmentInvocations, resolve->fragmentInvocations) << spec;
    else
      EXPECT_EQ(restore->fragmentInvocations, resolve->fragmentInvocations) << spec;
    EXPECT_GE(restoreFloor->minimumBytes, restoreFloor->fragmentInvocations * (2 * (4 + 4) + 4 + 4)) << spec;
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

TEST(ForeignLayout, ExtraLightTexturesMustHoldFloats) {
  testing_support::context();
  MiniatureStk host;
  host::Texture bytes = host::makeTexture2D(GL_RGBA8, kWidth, kHeight, "mini.rgba8");
  retroaa::Description description;
  description.config.method = retroaa::Method::Edge;
  description.layout = host.layout();
  description.layout.extraLightTextures = {bytes};
  auto plugin = retroaa::Plugin::create(description);
  ASSERT_FALSE(plugin);
  EXPECT_EQ(plugin.error().code, retroaa::ErrorCode::InvalidLayout);
  EXPECT_NE(plugin.error().message.find("extraLightTextures[0]"), std::string::npos) << plugin.error().message;
}

TEST(ForeignLayout, AModelPassWithMultisamplingOffIsNamedInAWarningOnce) {
  // Irrlicht (SuperTuxKart's engine) disables GL_MULTISAMPLE on a window without MSAA: a model pass
  // drawn so into the MSAA G-buffer holds no coverage. The plugin says so, once.
  testing_support::context();
  MiniatureStk host;
  auto plugin = createPlugin(host, "resolve@samples=4");
  ASSERT_TRUE(plugin);
  auto multisampleWarnings = [&] {
    int found = 0;
    for (const std::string& warning : plugin->warnings())
      found += warning.find("GL_MULTISAMPLE is disabled") != std::string::npos;
    return found;
  };
  runFrame(host, *plugin);
  EXPECT_EQ(multisampleWarnings(), 0);
  glDisable(GL_MULTISAMPLE);
  runFrame(host, *plugin);
  runFrame(host, *plugin);
  glEnable(GL_MULTISAMPLE);
  EXPECT_EQ(multisampleWarnings(), 1);
}

// Irrlicht's perspective projection (SuperTuxKart's) puts clip z in 0 … w, as Direct3D does; under GL's default
// depth range its window depth is 0.5 + 0.5 × a GL projection's (DepthBufferEncoding::PerspectiveClipZeroToOne).
// A frame whose projection disagrees with the layout's encoding is named in one warning; one that agrees, in none.
TEST(ForeignLayout, AProjectionWhoseClipZDisagreesWithTheLayoutIsNamedOnce) {
  testing_support::context();
  const float n = 1.0f, f = 1200.0f;
  retroaa::FrameInfo irrlicht{1.396f, n, f};  // buildProjectionMatrixPerspectiveFovLH, column-major
  irrlicht.projectionMatrix[0] = 1.2f, irrlicht.projectionMatrix[5] = 1.6f;
  irrlicht.projectionMatrix[10] = f / (f - n), irrlicht.projectionMatrix[11] = 1.0f;
  irrlicht.projectionMatrix[14] = -n * f / (f - n);
  retroaa::FrameInfo gl = irrlicht;  // the same planes, clip z -w … w
  gl.projectionMatrix[10] = (f + n) / (f - n), gl.projectionMatrix[14] = -2.0f * n * f / (f - n);
  auto count = [](const retroaa::Plugin& plugin, const char* text) {
    int found = 0;
    for (const std::string& warning : plugin.warnings()) found += warning.find(text) != std::string::npos;
    return found;
  };
  for (const auto encoding :
       {retroaa::DepthBufferEncoding::Perspective, retroaa::DepthBufferEncoding::PerspectiveClipZeroToOne}) {
    const bool zeroToOne = encoding == retroaa::DepthBufferEncoding::PerspectiveClipZeroToOne;
    MiniatureStk host;
    host.depthEncoding = encoding;
    auto plugin = createPlugin(host, "resolve@samples=4");
    ASSERT_TRUE(plugin);
    for (int frame = 0; frame < 2; ++frame) {
      host.solidPass(plugin->geometryFramebuffer());
      ASSERT_TRUE(plugin->resolve(zeroToOne ? irrlicht : gl));
      ASSERT_TRUE(plugin->shade([&](GLuint target) { host.lighting(target); }));
    }
    EXPECT_EQ(count(*plugin, "clip z runs"), 0) << int(encoding);
    host.solidPass(plugin->geometryFramebuffer());
    ASSERT_TRUE(plugin->resolve(zeroToOne ? gl : irrlicht));  // the other convention than the layout's
    ASSERT_TRUE(plugin->resolve(zeroToOne ? gl : irrlicht));
    EXPECT_EQ(
        count(*plugin, zeroToOne ? "clip z runs -w … w (GL's) but depthBufferEncoding is PerspectiveClipZeroToOne"
                                 : "clip z runs 0 … w (Direct3D's, Irrlicht's) but depthBufferEncoding is Perspective"),
        1);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

TEST(ForeignLayout, ReconstructTakesTheSpheremapNormalsOfItsPrepass) {
  // The stock single-sample frame, "tonemapped" as the light itself into the display; reconstruct then
  // rebuilds sub-samples from its MSAA prepass, whose normals are STK's spheremap pairs. Pixels whose
  // every sub-sample lies on their own surface keep their colour exactly; the edge's pixels change.
  testing_support::context();
  MiniatureStk host;
  host.curvature = -0.15f;  // shading varies from pixel to pixel inside surface A
  auto plugin = createPlugin(host, "reconstruct@samples=4");
  ASSERT_TRUE(plugin);
  runFrame(host, *plugin);
  glBlitNamedFramebuffer(host.light, host.displayTarget, 0, 0, kWidth, kHeight, 0, 0, kWidth, kHeight,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  const auto before = host.read(host.display);
  ASSERT_TRUE(plugin->post());
  const auto after = host.read(host.display);
  int interior = 0, changedEdge = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const float line = x + 0.37f * y;
      const size_t p = size_t(y) * kWidth + x;
      if (line < 10.3f - 2.5f || line > 10.3f + 1.5f) {
        ++interior;
        EXPECT_EQ(glm::vec3(after[p]), glm::vec3(before[p])) << "interior pixel " << x << "," << y;
      } else {
        changedEdge += glm::vec3(after[p]) != glm::vec3(before[p]);
      }
    }
  EXPECT_GT(interior, kWidth * kHeight / 2);
  EXPECT_GT(changedEdge, kHeight / 2) << "the edge's pixels mix both surfaces";
  EXPECT_TRUE(plugin->warnings().empty()) << plugin->warnings().front();
}
