// GBufferLayout::displayEncoding honoured by every pass that mixes or thresholds the display's colours:
// the same picture stored as linear light (Linear) or gamma-encoded (DisplayEncoded) is filtered into
// the same picture. Each filter runs on an RGBA16F display (no 8-bit rounding between the two
// encodings) holding a slanted edge between two colours, once encoded and once decoded.
#include "commands.h"
#include "test_support.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

using namespace testing_support;

namespace {

constexpr int kWidth = 48, kHeight = 24;

// The slanted edge: below the line y = 6.3 + x / 5 one surface, above it the other.
bool belowEdge(float x, float y) { return y < 6.3f + x / 5.0f; }
const char* kSampleDepths =
    "gl_FragDepth = (float(y) + position.y < 6.3 + (float(x) + position.x) / 5.0) ? 0.5 : 0.9;"
    " outNormal = vec4(0.0, 0.0, 1.0, 0.5);";

// The edge's two colours, gamma-encoded: `dark` picks two whose linear contrast is under FXAA's
// thresholds while their encoded contrast is over them. `shift` moves the edge up by that many pixels.
std::vector<float> encodedEdgeImage(bool dark, float shift = 0.0f) {
  const float below[3] = {0.80f, 0.62f, 0.20f}, above[3] = {0.10f, 0.05f, 0.45f};
  const float darkBelow[3] = {0.19f, 0.19f, 0.19f}, darkAbove[3] = {0.06f, 0.06f, 0.06f};
  std::vector<float> image(size_t(kWidth) * kHeight * 4, 1.0f);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool side = belowEdge(x + 0.5f, y + 0.5f - shift);
        image[(size_t(y) * kWidth + x) * 4 + c] =
            dark ? (side ? darkBelow[c] : darkAbove[c]) : (side ? below[c] : above[c]);
      }
  return image;
}

std::vector<float> decoded(std::vector<float> image) {
  for (size_t i = 0; i < image.size(); ++i)
    if (i % 4 != 3) image[i] = srgbToLinear(image[i]);
  return image;
}

// `spec`'s post passes on each of `frames` in turn (RGBA, GL rows) in an RGBA16F display of `encoding`; the
// last filtered display. A method with a prepass gets kSampleDepths per sample and the edge's depths per pixel.
std::vector<float> filtered(const std::string& spec, retroaa::DisplayEncoding encoding,
                            const std::vector<std::vector<float>>& frames) {
  const std::vector<float>& image = frames.back();
  SyntheticFrame frame(kWidth, kHeight);
  const host::HostTargets& t = frame.renderer->targets();
  retroaa::Description description;
  description.config = app::parseMethodSpec(spec, {}).config;
  description.layout = patch::describeHostGBuffer(t);
  description.layout.normalsInViewSpace = true;
  description.layout.displayEncoding = encoding;
  const StandInDisplay display(GL_RGBA16F, kWidth, kHeight);
  display.describeIn(description.layout);
  std::vector<uint32_t> depth(size_t(kWidth) * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      depth[size_t(y) * kWidth + x] = uint32_t((belowEdge(x + 0.5f, y + 0.5f) ? 0.5 : 0.9) * 0xFFFFFF) << 8;
  glTextureSubImage2D(t.depthStencil, 0, 0, 0, kWidth, kHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth.data());
  const std::vector<glm::vec4> normals(size_t(kWidth) * kHeight, glm::vec4(0, 0, 1, 0.5f));
  glTextureSubImage2D(t.normal, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, normals.data());
  std::vector<float> out(image.size());
  retroaa::FrameInfo frameInfo{verticalFovFor(0.8f, kWidth, kHeight), 0.1f, 100.0f};
  const glm::mat4 projection = glm::perspective(frameInfo.verticalFovRadians, float(kWidth) / kHeight, 0.1f, 100.0f);
  std::copy(&projection[0][0], &projection[0][0] + 16, frameInfo.projectionMatrix);  // a history for `temporal`
  {
    auto plugin = retroaa::Plugin::create(description);
    EXPECT_TRUE(plugin) << spec << ": " << plugin.error().message;
    for (size_t f = 0; plugin && f < frames.size(); ++f) {
      glTextureSubImage2D(display.texture, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, frames[f].data());
      if (plugin.value()->prepassFramebuffer())
        writePerSample(plugin.value()->prepassFramebuffer(), kWidth, kHeight, kSampleDepths);
      EXPECT_TRUE(plugin.value()->resolve(frameInfo)) << spec;
      EXPECT_TRUE(plugin.value()->post()) << spec;
    }
  }
  glGetTextureImage(display.texture, 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << spec;
  return out;
}

int changedPixels(const std::vector<float>& before, const std::vector<float>& after) {
  int count = 0;
  for (size_t p = 0; p < before.size() / 4; ++p)
    count += std::abs(before[p * 4] - after[p * 4]) > 1e-3f || std::abs(before[p * 4 + 2] - after[p * 4 + 2]) > 1e-3f;
  return count;
}

}  // namespace

TEST(DisplayEncoding, EveryFilterThatMixesColoursMixesTheSamePictureStoredLinearOrEncoded) {
  // Linear: the stored values are light and are mixed as stored. DisplayEncoded: they are decoded
  // first and encoded again. Either way the picture after the filter is the same light. A pass that
  // ignored the encoding would decode the linear display (darkening every mix) or threshold linear
  // values (other edges).
  // `temporal` accumulates two frames whose edges lie a pixel apart.
  const std::vector<float> encoded = encodedEdgeImage(false), linear = decoded(encoded);
  const std::vector<float> encodedBefore = encodedEdgeImage(false, 1.0f), linearBefore = decoded(encodedBefore);
  for (const char* spec : {"smaa", "coverage", "reconstruct", "resolve+smaa", "temporal@temporal_before_tonemap=off"}) {
    const bool twoFrames = std::string(spec).find("temporal") != std::string::npos;
    const std::vector<float> fromEncoded =
        twoFrames ? filtered(spec, retroaa::DisplayEncoding::DisplayEncoded, {encodedBefore, encoded})
                  : filtered(spec, retroaa::DisplayEncoding::DisplayEncoded, {encoded});
    const std::vector<float> fromLinear = twoFrames
                                              ? filtered(spec, retroaa::DisplayEncoding::Linear, {linearBefore, linear})
                                              : filtered(spec, retroaa::DisplayEncoding::Linear, {linear});
    EXPECT_GE(changedPixels(encoded, fromEncoded), kWidth / 2) << spec << ": the edge was filtered";
    double worst = 0;
    for (size_t i = 0; i < encoded.size(); ++i)
      if (i % 4 != 3) worst = std::max(worst, double(std::abs(srgbToLinear(fromEncoded[i]) - fromLinear[i])));
    EXPECT_LT(worst, 2e-3) << spec << ": the same light, whichever way the display stores it";
  }
}

TEST(DisplayEncoding, FxaaThresholdsPerceptualLumaOnALinearDisplay) {
  // A dark edge: encoded 0.06 against 0.19 is a contrast FXAA filters; the same light stored linearly
  // (0.005 against 0.03) is under its absolute floor. FXAA's thresholds are written for perceptual
  // luma: the linear display is encoded for them, so the same pixels are filtered. (Its blend mixes the
  // values as stored, as Lottes' does with whatever its input holds.)
  const std::vector<float> encoded = encodedEdgeImage(true), linear = decoded(encoded);
  for (const char* spec : {"fxaa", "resolve+fxaa"}) {
    const std::vector<float> fromEncoded = filtered(spec, retroaa::DisplayEncoding::DisplayEncoded, {encoded});
    const std::vector<float> fromLinear = filtered(spec, retroaa::DisplayEncoding::Linear, {linear});
    ASSERT_GE(changedPixels(encoded, fromEncoded), kWidth / 2) << spec;
    for (size_t p = 0; p < encoded.size() / 4; ++p)
      EXPECT_EQ(std::abs(encoded[p * 4] - fromEncoded[p * 4]) > 1e-3f,
                std::abs(linear[p * 4] - fromLinear[p * 4]) > 1e-4f)
          << spec << " pixel " << p % kWidth << "," << p / kWidth << ": filtered on one display, not the other";
  }
}
