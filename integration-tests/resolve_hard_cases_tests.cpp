// The resolve on hand-written multisampled G-buffers: each pixel one hard case (all background,
// NaN/Inf samples, zero-length and opposing normals, 0.1 m beside 1e6 m, even-N medians, FSO's
// reference choice). Every sample's attachments are written exactly by a per-sample shader.
#include "depth_codec.h"
#include "test_support.h"

#include <cmath>
#include <limits>

using namespace testing_support;
namespace codec = host::depth_codec;

namespace {

constexpr int kWidth = 64, kHeight = 48;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

using Sample = SyntheticSample;
Sample background() { return backgroundSample(); }
Sample surface(float depth, glm::vec3 normal = {0, 0, 1}) { return surfaceSample(depth, normal); }

class ResolveHardCases : public ::testing::Test {
 protected:
  void SetUp() override {
    context();
    scene_ = host::parseScene(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
      "materials": [{"name": "m"}], "objects": []})",
                              "empty", ".");
    renderer_ = std::make_unique<host::Renderer>(scene_, kWidth, kHeight);
  }

  // Resolves `pixels` (each a list of samples, at x = 0, 1, ... of row 0) and reads the host G-buffer.
  // `compute`: resolve_compute=on. The pass's statistics are kept in resolvePass_.
  void resolve(const std::vector<std::vector<Sample>>& pixels, int samples, retroaa::ResolveWeighting weighting,
               bool compute = false) {
    retroaa::Config config;
    config.method = retroaa::Method::Resolve;
    config.samples = samples;
    config.resolveWeighting = weighting;
    config.resolveCompute = compute;
    config.measureGpuTime = true;
    auto hooks = patch::RetroaaHooks::create(renderer_->targets(), config);
    ASSERT_TRUE(hooks) << hooks.error().message;
    retroaa::Plugin& plugin = hooks.value()->plugin();
    // The driver may back a request with more samples (llvmpipe: 4 for 1x and 2x); each pixel's list
    // is then stretched over what was allocated, keeping its proportions.
    std::vector<std::vector<Sample>> grid(pixels.begin(), pixels.end());
    granted_ = fillGeometry(plugin, kWidth, kHeight, grid);

    retroaa::FrameInfo frame;
    frame.verticalFovRadians = 1.0f;
    ASSERT_TRUE(plugin.resolve(frame));
    for (int a = 0; a < 5; ++a) {
      const GLuint textures[] = {renderer_->targets().color, renderer_->targets().position, renderer_->targets().normal,
                                 renderer_->targets().specular, renderer_->targets().emissive};
      out_[a].resize(size_t(kWidth) * kHeight);
      glGetTextureImage(textures[a], 0, GL_RGBA, GL_FLOAT, GLsizei(out_[a].size() * sizeof(glm::vec4)), out_[a].data());
    }
    depth_.resize(size_t(kWidth) * kHeight);
    glGetTextureImage(renderer_->targets().depthStencil, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth_.size() * 4),
                      depth_.data());
    resolvePass_ = {};
    for (const retroaa::PassStats& pass : plugin.waitForStats().passes)
      if (pass.name == "resolve") resolvePass_ = pass;
    warnings_ = plugin.warnings();
  }

  glm::vec4 attachment(int a, int x) const { return out_[a][x]; }
  float depthMetres(int x) const { return codec::decode(out_[1][x].z); }
  bool isBackground(int x) const { return codec::isBackground(out_[1][x].z); }
  void expectFinite(int x) const {
    for (int a = 0; a < 5; ++a)
      for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(out_[a][x][c])) << "pixel " << x << " attachment " << a;
    EXPECT_TRUE(std::isfinite(depth_[x]));
  }

  host::Scene scene_;
  std::unique_ptr<host::Renderer> renderer_;
  std::vector<glm::vec4> out_[5];
  std::vector<float> depth_;
  int granted_ = 0;
  retroaa::PassStats resolvePass_;
  std::vector<std::string> warnings_;
};

}  // namespace

TEST_F(ResolveHardCases, EveryHardCaseGivesAFiniteSensibleResult) {
  Sample nanNormal = surface(10), infPosition = surface(10), nanAll = surface(10);
  nanNormal.attachments[2] = glm::vec4(kNaN, 0, 1, 0.5f);
  infPosition.attachments[1].x = kInf;
  for (glm::vec4& a : nanAll.attachments) a = glm::vec4(kNaN);
  const std::vector<std::vector<Sample>> pixels = {
      /*0 all background*/ {background(), background(), background(), background()},
      /*1 NaN normal    */ {surface(10), nanNormal, surface(10), surface(10)},
      /*2 Inf position  */ {surface(10), surface(10), infPosition, surface(10)},
      /*3 zero normals  */
      {surface(5, glm::vec3(0)), surface(5, glm::vec3(0)), surface(5, glm::vec3(0)), surface(5, glm::vec3(0))},
      /*4 0.1 m & 1e6 m */ {surface(0.1f), surface(0.1f), surface(1e6f), surface(1e6f)},
      /*5 opposing      */
      {surface(10, {0, 0, 1}), surface(10, {0, 0, -1}), surface(10, {0, 0, 1}), surface(10, {0, 0, -1})},
      /*6 depth step    */ {surface(10), surface(10.001f), surface(20), surface(30)},
      /*7 silhouette    */ {surface(10), background(), surface(10), background()},
      /*8 all NaN       */ {nanAll, nanAll, nanAll, nanAll},
  };
  resolve(pixels, 4, retroaa::ResolveWeighting::Median);
  for (int x = 0; x < int(pixels.size()); ++x) expectFinite(x);

  EXPECT_TRUE(isBackground(0));
  EXPECT_NEAR(attachment(4, 0).b, 0.3f, 1e-3f);  // the sky survives in emissive
  EXPECT_EQ(depth_[0], 1.0f);

  for (int x : {1, 2}) {
    EXPECT_NEAR(depthMetres(x), 10.0f, 0.01f) << x;
    EXPECT_NEAR(glm::length(glm::vec3(attachment(2, x))), 1.0f, 1e-3f) << x;
  }
  EXPECT_NEAR(glm::length(glm::vec3(attachment(2, 3))), 1.0f, 1e-3f);  // zero normals: a unit fallback
  EXPECT_NEAR(depthMetres(4), 0.1f, 1e-4f);                            // a real sample's depth, not the 5e5 m mean
  EXPECT_NEAR(glm::length(glm::vec3(attachment(2, 5))), 1.0f, 1e-3f);  // opposing normals cancel: fallback
  EXPECT_NEAR(depthMetres(6), 10.0005f, 0.01f);                        // 10 and 10.001 merge; 20 and 30 stay out
  EXPECT_FLOAT_EQ(depth_[6], surface(10.001f).depthBuffer.x);          // reference sample's depth-buffer value
  EXPECT_FALSE(isBackground(7));                 // median of {10, 10, bg, bg} is the nearer middle: the object
  EXPECT_NEAR(attachment(4, 7).b, 0.0f, 1e-3f);  // no sky mixed into the object's emissive
  EXPECT_TRUE(isBackground(8));
}

TEST_F(ResolveHardCases, FsoMedianIsTheFartherMiddleAndBackgroundCountsAsNearest) {
  resolve({{surface(10), surface(10.001f), surface(20), surface(30)},
           {surface(10), background(), surface(10), background()},
           {surface(10), background(), background(), background()}},
          4, retroaa::ResolveWeighting::Fso);
  expectFinite(0);
  EXPECT_NEAR(depthMetres(0), 20.0f, 0.05f);
  // FSO's background has view z 0, the nearest value: a 2/2 silhouette keeps the object, 3/1 does not
  EXPECT_FALSE(isBackground(1));
  EXPECT_NEAR(attachment(4, 1).b, 0.0f, 1e-3f);  // and no sky in the object's emissive
  EXPECT_TRUE(isBackground(2));
}

TEST_F(ResolveHardCases, WindowWeighsSymmetricallyAroundTheFartherMiddle) {
  // Eq. 1's footprint at 20 m for this 64×48 frame (vertical fov 1 rad): samples 1.5 footprints either
  // side of the median weigh fully and alike, so the depth stays the median's; 6 footprints away, none.
  const float aspect = float(kWidth) / float(kHeight);
  const float footprint = 20.0f * std::tan(2.0f * std::atan(std::tan(0.5f) * aspect) / float(kWidth));
  resolve({{surface(20 - 1.5f * footprint), surface(20), surface(20), surface(20 + 1.5f * footprint)},
           {surface(20), surface(20), surface(20), surface(20 + 6 * footprint)},
           {surface(20), surface(20), surface(20), surface(20 + 3.75f * footprint)}},
          4, retroaa::ResolveWeighting::Window);
  EXPECT_NEAR(depthMetres(0), 20.0f, 0.02f);
  EXPECT_NEAR(depthMetres(1), 20.0f, 0.02f);
  // halfway down the falling edge (2.5 → 5 footprints) it weighs 1/2: the mean moves 3.75·0.5/3.5 footprints
  EXPECT_NEAR(depthMetres(2), 20.0f + 3.75f * footprint * 0.5f / 3.5f, 0.02f);
  EXPECT_FLOAT_EQ(depth_[1], surface(20).depthBuffer.x);  // ours keep the reference's depth-buffer value
}

TEST_F(ResolveHardCases, EvenSampleCountMedianIsARealSample) {
  // Half the samples at 10 m, half at 30 m, at every even count the context grants.
  for (int samples : {2, 4, 8}) {
    if (samples > context().info().maxSamples) break;
    std::vector<Sample> pixel;
    for (int s = 0; s < samples; ++s) pixel.push_back(surface(s < samples / 2 ? 10.0f : 30.0f));
    resolve({pixel}, samples, retroaa::ResolveWeighting::Median);
    if (HasFatalFailure()) return;
    EXPECT_NEAR(depthMetres(0), 10.0f, 0.01f) << samples << " samples requested, " << granted_ << " allocated";
  }
}

TEST_F(ResolveHardCases, FrontAndBackPickTheExtremes) {
  resolve({{surface(10), surface(20), surface(30), surface(40)}}, 4, retroaa::ResolveWeighting::Front);
  EXPECT_NEAR(depthMetres(0), 10.0f, 0.01f);
  resolve({{surface(10), surface(20), surface(30), surface(40)}}, 4, retroaa::ResolveWeighting::Back);
  EXPECT_NEAR(depthMetres(0), 40.0f, 0.05f);
}

TEST_F(ResolveHardCases, TheComputeResolveWritesTheSameGBufferAndDepthBitForBit) {
  // Every hard case above and a spread of ordinary pixels, under every weighting: resolve_compute=on
  // writes the host's five attachments and its depth exactly as the full-screen pass does (NaN included,
  // compared as bits). The compute pass runs one invocation per pixel of whole 8×8 tiles; its depth's
  // copy draws as many fragments as the full-screen resolve, which runs no compute invocation.
  Sample nanNormal = surface(10), infPosition = surface(10);
  nanNormal.attachments[2] = glm::vec4(kNaN, 0, 1, 0.5f);
  infPosition.attachments[1].x = kInf;
  std::vector<std::vector<Sample>> pixels = {
      {background(), background(), background(), background()},
      {surface(10), nanNormal, surface(10), surface(10)},
      {surface(10), surface(10), infPosition, surface(10)},
      {surface(5, glm::vec3(0)), surface(5, glm::vec3(0)), surface(5, glm::vec3(0)), surface(5, glm::vec3(0))},
      {surface(0.1f), surface(0.1f), surface(1e6f), surface(1e6f)},
      {surface(10, {0, 0, 1}), surface(10, {0, 0, -1}), surface(10, {0, 0, 1}), surface(10, {0, 0, -1})},
      {surface(10), surface(10.001f), surface(20), surface(30)},
      {surface(10), background(), surface(10), background()},
  };
  for (int x = 0; x < 40; ++x) {  // depths and normals that vary across the row, as a frame's do
    const float depth = 2.0f + 0.37f * float(x);
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.05f * float(x % 7), 0.3f, 1.0f));
    pixels.push_back({surface(depth), surface(depth * (1.0f + 0.002f * float(x % 5)), tilted),
                      x % 3 ? surface(depth + 3.0f) : background(), surface(depth * 1.01f, tilted)});
  }
  auto bits = [](const auto& values) {
    const auto* bytes = reinterpret_cast<const uint8_t*>(values.data());
    return std::vector<uint8_t>(bytes, bytes + values.size() * sizeof(values[0]));
  };
  using W = retroaa::ResolveWeighting;
  for (W weighting : {W::Median, W::Front, W::Back, W::Fso, W::Mean, W::Window}) {
    const char* name = retroaa::toString(weighting);
    resolve(pixels, 4, weighting, false);
    if (HasFatalFailure()) return;
    const retroaa::PassStats fullScreenPass = resolvePass_;
    std::vector<uint8_t> fullScreen[5];
    for (int a = 0; a < 5; ++a) fullScreen[a] = bits(out_[a]);
    const std::vector<uint8_t> fullScreenDepth = bits(depth_);
    resolve(pixels, 4, weighting, true);
    if (HasFatalFailure()) return;
    for (int a = 0; a < 5; ++a) EXPECT_TRUE(bits(out_[a]) == fullScreen[a]) << name << ": attachment " << a;
    EXPECT_TRUE(bits(depth_) == fullScreenDepth) << name << ": depth";
    EXPECT_EQ(resolvePass_.computeInvocations, uint64_t(kWidth * kHeight)) << name;  // 64×48: whole tiles
    EXPECT_EQ(resolvePass_.fragmentInvocations, fullScreenPass.fragmentInvocations) << name << ": the depth's copy";
    EXPECT_GE(fullScreenPass.fragmentInvocations, uint64_t(kWidth * kHeight)) << name;
    EXPECT_EQ(fullScreenPass.computeInvocations, 0u) << name;
    EXPECT_TRUE(warnings_.empty()) << warnings_.front();
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
