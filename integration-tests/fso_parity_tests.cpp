// FreeSpace Open parity: the plugin's `fso` weighting against a CPU reference of FSO's msaa-f.sdr,
// on FSO's current G-buffer (position z through z-compress.sdr), and the compressed z itself.
//
// The reference is written from the facts of FSO's shader (read at scp-fs2open/fs2open.github.com
// 13cf39f6): view z (negative in front, 0 for background) decompressed per sample; the median is
// element 1 of 4, 3 of 8, 7 of 16 in ascending view z (what FSO's partial sorting networks leave there),
// front first for other counts; footprint tan(fov / height) with the vertical fov; the weight
// max(step(-0.001, dist)·step(-0.001, z), smoothstep(dist + 5f, dist + 2.5f, z)·smoothstep(dist − 2.5f,
// dist + 5f, z)) with f = dist·footprint and smoothstep as Mesa and NVIDIA evaluate it for reversed
// edges; every output the weighted mean, z recompressed, normal normalize(Σw·n) with alpha Σw·a/Σw, and
// the depth buffer the weighted mean of the samples' depths.
#include "depth_codec.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace testing_support;

namespace {

constexpr int kWidth = 64, kHeight = 48;
constexpr float kFovY = 0.87266463f;  // 50°
constexpr float kFarZ = 2.0e6f;       // the host scene's far plane: FSO's GLOBAL_FAR_Z
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

glm::vec4 throughHalf(glm::vec4 v) {
  using testing_support::throughHalf;
  return {throughHalf(v.x), throughHalf(v.y), throughHalf(v.z), throughHalf(v.w)};
}
glm::vec4 throughUnorm8(glm::vec4 v) { return glm::round(glm::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f; }
float throughUnorm24(float v) { return float(std::round(double(v) * 16777215.0) / 16777215.0); }

// One sample as FSO's model shader leaves it: position z compressed, background all zero.
SyntheticSample fsoSurface(float distance, glm::vec3 normal = {0, 0, 1}, glm::vec3 albedo = glm::vec3(0.5f)) {
  const float depthBuffer = 1.0f - 1.0f / (1.0f + 0.01f * distance);  // any monotonic value in [0, 1)
  return {{glm::vec4(albedo, 1), glm::vec4(0.01f, -0.02f, host::fso_z::compress(-distance, kFarZ), 1),
           glm::vec4(normal, 0.5f), glm::vec4(0.04f, 0.05f, 0.06f, 1), glm::vec4(0.1f * albedo, 1)},
          glm::vec4(depthBuffer)};
}
SyntheticSample fsoBackground() {
  return {{glm::vec4(0), glm::vec4(0), glm::vec4(0), glm::vec4(0), glm::vec4(0.1f, 0.2f, 0.3f, 1)}, glm::vec4(1)};
}

// What the G-buffer holds of a sample once written (FP16 attachments, RGBA8 specular, D24 depth).
SyntheticSample asStored(SyntheticSample s) {
  for (int a = 0; a < 5; ++a)
    s.attachments[a] = a == 3 ? throughUnorm8(s.attachments[a]) : throughHalf(s.attachments[a]);
  s.depthBuffer.x = throughUnorm24(s.depthBuffer.x);
  return s;
}

// GLSL's smoothstep as both drivers evaluate it, reversed edges included.
float measuredSmoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
float step(float edge, float x) { return x < edge ? 0.0f : 1.0f; }

struct FsoOutput {
  glm::vec4 attachments[5];
  float depth;
};

// FSO's msaa-f.sdr on one pixel's stored samples.
FsoOutput fsoReference(const std::vector<SyntheticSample>& samples) {
  const int n = int(samples.size());
  std::vector<float> z(n);
  for (int i = 0; i < n; ++i) z[i] = host::fso_z::uncompress(samples[i].attachments[1].z, kFarZ);
  float dist;
  if (n == 4 || n == 8 || n == 16) {
    std::vector<float> sorted = z;
    std::sort(sorted.begin(), sorted.end());
    dist = sorted[n / 2 - 1];
  } else {
    dist = *std::max_element(z.begin(), z.end());
  }
  const float texelWidthFactor = std::tan(kFovY / float(kHeight));
  FsoOutput out{};
  glm::vec4 pos(0), normal(0);
  float weight = 0, depth = 0;
  for (int i = 0; i < n; ++i) {
    // std::fmax keeps the number where the GPU's max meets the NaN of a zero-width smoothstep
    const float w = std::fmax(
        step(-0.001f, dist) * step(-0.001f, z[i]),
        measuredSmoothstep(dist + dist * texelWidthFactor * 5.0f, dist + dist * texelWidthFactor * 2.5f, z[i]) *
            measuredSmoothstep(dist - dist * texelWidthFactor * 2.5f, dist + dist * texelWidthFactor * 5.0f, z[i]));
    glm::vec4 localPos = samples[i].attachments[1];
    localPos.z = z[i];
    pos += localPos * w;
    for (int a : {0, 3, 4}) out.attachments[a] += samples[i].attachments[a] * w;
    normal += samples[i].attachments[2] * w;
    depth += samples[i].depthBuffer.x * w;
    weight += w;
  }
  pos /= weight;
  pos.z = host::fso_z::compress(pos.z, kFarZ);
  out.attachments[1] = pos;
  for (int a : {0, 3, 4}) out.attachments[a] /= weight;
  out.attachments[2] = glm::vec4(glm::normalize(glm::vec3(normal)), normal.w / weight);
  out.depth = depth / weight;
  return out;
}

bool isFinite(glm::vec4 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

class FsoParity : public ::testing::Test {
 protected:
  void SetUp() override {
    context();
    scene_ = host::parseScene(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y_deg": 50,
      "far": 2000000}, "materials": [{"name": "m"}], "objects": [], "position_depth": "fso-compressed"})",
                              "empty", ".");
    renderer_ = std::make_unique<host::Renderer>(scene_, kWidth, kHeight);
  }

  // Resolves one pixel per case (row 0 onwards) with `fso` at `samples` and reads the host's G-buffer.
  // Returns false when the context grants another sample count.
  bool resolve(const std::vector<std::vector<SyntheticSample>>& pixels, int samples) {
    retroaa::Config config;
    config.method = retroaa::Method::Resolve;
    config.samples = samples;
    config.resolveWeighting = retroaa::ResolveWeighting::Fso;
    auto hooks = patch::RetroaaHooks::create(renderer_->targets(), config);
    EXPECT_TRUE(hooks) << hooks.error().message;
    if (!hooks) return false;
    retroaa::Plugin& plugin = hooks.value()->plugin();
    if (plugin.stats().samples != samples) return false;
    fillGeometry(plugin, kWidth, kHeight, pixels);
    retroaa::FrameInfo frame;
    frame.verticalFovRadians = kFovY;
    EXPECT_TRUE(plugin.resolve(frame));
    const host::HostTargets& t = renderer_->targets();
    const GLuint textures[] = {t.color, t.position, t.normal, t.specular, t.emissive};
    for (int a = 0; a < 5; ++a) {
      out_[a].resize(size_t(kWidth) * kHeight);
      glGetTextureImage(textures[a], 0, GL_RGBA, GL_FLOAT, GLsizei(out_[a].size() * sizeof(glm::vec4)), out_[a].data());
    }
    depth_.resize(size_t(kWidth) * kHeight);
    glGetTextureImage(t.depthStencil, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth_.size() * 4), depth_.data());
    return true;
  }

  host::Scene scene_;
  std::unique_ptr<host::Renderer> renderer_;
  std::vector<glm::vec4> out_[5];
  std::vector<float> depth_;
};

// The issue's cases at `n` samples: flat, sloped, silhouettes, two surfaces, 3-way splits with
// background, far geometry, NaN and zero normals. Each is named for the failure message.
struct Case {
  std::string name;
  std::vector<SyntheticSample> samples;
};
std::vector<Case> parityCases(int n) {
  std::vector<Case> cases;
  auto footprint = [](float d) { return d * std::tan(kFovY / float(kHeight)); };
  auto spread = [&](const std::string& name, float d, float stepFootprints) {
    std::vector<SyntheticSample> s;
    for (int i = 0; i < n; ++i)  // a shuffled order, so nothing depends on sample positions
      s.push_back(fsoSurface(d + float((i * 3) % n) * stepFootprints * footprint(d),
                             glm::normalize(glm::vec3(0.1f * float(i), 0.2f, 1.0f)),
                             glm::vec3(0.2f + 0.15f * float(i % 5))));
    cases.push_back({name, s});
  };
  spread("flat at 20 m", 20.0f, 0.0f);
  for (float slope : {0.1f, 0.5f, 1.0f, 2.0f, 4.0f})
    spread("sloped " + std::to_string(slope) + " footprints at 30 m", 30.0f, slope);
  for (int objects = 1; objects < n; ++objects) {
    std::vector<SyntheticSample> s;
    for (int i = 0; i < n; ++i) s.push_back(i < objects ? fsoSurface(15.0f + 0.01f * float(i)) : fsoBackground());
    cases.push_back({"silhouette " + std::to_string(objects) + "/" + std::to_string(n - objects), s});
  }
  for (float apart : {-6.0f, -4.0f, -2.5f, -1.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f}) {
    std::vector<SyntheticSample> s;
    const float d = 40.0f;
    for (int i = 0; i < n; ++i)
      s.push_back(i % 2 ? fsoSurface(d + apart * footprint(d), {0, 1, 0}, glm::vec3(0.9f))
                        : fsoSurface(d, {0, 0, 1}, glm::vec3(0.1f)));
    cases.push_back({"two surfaces " + std::to_string(apart) + " footprints apart", s});
  }
  for (float d : {12.0f, 400.0f, 2500.0f}) {
    std::vector<SyntheticSample> s;
    for (int i = 0; i < n; ++i)
      s.push_back(i % 3 == 0 ? fsoBackground()
                             : fsoSurface(i % 3 == 1 ? d : d * 1.5f, {1, 0, 0}, glm::vec3(0.3f * float(i % 3))));
    cases.push_back({"3-way split with background at " + std::to_string(d) + " m", s});
  }
  for (float d : {1.0e4f, 3.0e4f, 1.0e5f}) spread("far geometry at " + std::to_string(d) + " m", d, 0.7f);
  {
    std::vector<SyntheticSample> s;
    for (int i = 0; i < n; ++i) s.push_back(fsoSurface(25.0f, i == 1 ? glm::vec3(0) : glm::vec3(0, 0, 1)));
    cases.push_back({"one zero normal", s});
  }
  {
    std::vector<SyntheticSample> s;
    for (int i = 0; i < n; ++i) s.push_back(fsoSurface(25.0f, glm::vec3(0)));
    cases.push_back({"all normals zero", s});
  }
  {
    std::vector<SyntheticSample> s;
    for (int i = 0; i < n; ++i) s.push_back(fsoSurface(25.0f, i == 2 ? glm::vec3(kNaN, 0, 1) : glm::vec3(0, 0, 1)));
    cases.push_back({"one NaN normal", s});
  }
  return cases;
}

}  // namespace

TEST(FsoCompressedZ, SegmentsMeetAndRoundTripExactly) {
  for (float far : {kFarZ, 1.0e10f}) {  // this host's far plane, and FSO's default Max_draw_distance
    for (float boundary : {10.0f, 100.0f, 1570.0f, 3000.0f, 10000.0f, 100000.0f}) {
      const float below = host::fso_z::compress(-boundary * 0.99999f, far);
      const float at = host::fso_z::compress(-boundary, far);
      // continuous, except at 1570 m where the encoding jumps from +65 065 to just below 0
      if (boundary != 1570.0f) {
        EXPECT_NEAR(below, at, std::fabs(at) * 1e-3f) << boundary << " m, far " << far;
      }
    }
    EXPECT_NEAR(host::fso_z::compress(-far, far), -65000.0f, 1.0f);  // the far plane lands below FP16's maximum
    EXPECT_EQ(host::fso_z::compress(0.0f, far), 0.0f);               // background
    EXPECT_TRUE(host::fso_z::isBackground(0.0f, far));
    EXPECT_FALSE(host::fso_z::isBackground(host::fso_z::compress(-0.1f, far), far));
    for (double d = 0.1; d <= 1e6; d *= 1.01) {  // float in, float out: exact to rounding
      const float back = -host::fso_z::uncompress(host::fso_z::compress(-float(d), far), far);
      // Past 100 km with FSO's default far plane the last segment's rate is 6e-10 per metre, so
      // 2^(rate·Δ) sits within float's epsilon of 1: single precision itself keeps only ~150 m there.
      const double toleranceMetres = d > 1e5 && far > 1e7 ? 200.0 : d * 2e-5;
      EXPECT_NEAR(back, d, toleranceMetres) << d << " m, far " << far;
    }
  }
}

TEST(FsoCompressedZ, Fp16RoundTripErrorIsMeasuredPerDecade) {
  // Not a claim of ours but a property of FSO's encoding, printed for docs/methods/resolve.md; the
  // bounds only guard against a broken codec (segment constants, branch order).
  for (float far : {kFarZ, 1.0e10f}) {
    std::printf("far %.0e m:", double(far));
    for (double decade = 0.1; decade < 1e6; decade *= 10) {
      double worst = 0;
      for (double d = decade; d < decade * 10 && d <= 1e6; d *= 1.001) {
        const float back = -host::fso_z::uncompress(throughHalf(host::fso_z::compress(-float(d), far)), far);
        worst = std::max(worst, std::fabs(back - d) / d);
      }
      std::printf("  [%g, %g) m %.2e", decade, decade * 10, worst);
      if (decade < 1e5 || far < 1e7) {  // FSO's default far leaves FP16 no precision past 100 km (0.86)
        EXPECT_LT(worst, 3e-3) << "decade from " << decade << " m, far " << far;
      }
    }
    std::printf("\n");
  }
}

TEST_F(FsoParity, FsoWeightingComputesWhatFsosShaderComputes) {
  int checked = 0;
  for (int n : {4, 8}) {
    if (n > context().info().maxSamples) continue;
    // Inputs already representable in the targets' formats, so that writing them rounds nothing
    // (drivers differ in how they round to FP16) and the reference reads exactly what FSO would.
    std::vector<Case> cases = parityCases(n);
    std::vector<std::vector<SyntheticSample>> pixels;
    for (Case& c : cases) {
      for (SyntheticSample& sample : c.samples) sample = asStored(sample);
      pixels.push_back(c.samples);
    }
    ASSERT_LE(pixels.size(), size_t(kWidth));
    if (!resolve(pixels, n)) continue;
    for (size_t x = 0; x < cases.size(); ++x) {
      const FsoOutput want = fsoReference(cases[x].samples);
      const std::string where = cases[x].name + " at " + std::to_string(n) + " samples";
      for (int a = 0; a < 5; ++a) {
        const glm::vec4 got = out_[a][x];
        EXPECT_TRUE(isFinite(got)) << where << ", attachment " << a;  // ours, even where FSO's is not
        for (int c = 0; c < 4; ++c) {
          const float expected = want.attachments[a][c];
          if (!std::isfinite(expected)) continue;  // FSO's NaN: one of the deviations we keep
          // FP16 output: 1e-3 absolute, or relative for the compressed z of far geometry
          const float tolerance = std::max(1e-3f, std::fabs(expected) * 1e-3f);
          EXPECT_NEAR(got[c], expected, tolerance) << where << ", attachment " << a << " channel " << c;
        }
      }
      EXPECT_NEAR(depth_[x], want.depth, 1e-5f) << where << ": the depth buffer is the weighted mean";
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << "no sample count of 4 or 8 was granted";
}

TEST_F(FsoParity, WeightsFollowFsosAsymmetricWindow) {
  // Four samples spread over one footprint: FSO weights them about 0.16 / 0.22 / 0.28 / 0.34 (nearest
  // first, normalised); an equal-weight mean would put the albedo at the middle of the four, 0.5.
  const float d = 50.0f, footprint = d * std::tan(kFovY / float(kHeight));
  std::vector<SyntheticSample> pixel;
  for (int i = 0; i < 4; ++i)
    pixel.push_back(asStored(fsoSurface(d + float(i) * footprint / 3.0f, {0, 0, 1}, glm::vec3(float(i) / 3.0f))));
  ASSERT_TRUE(resolve({pixel}, 4)) << "4 samples not granted as such";
  const float weighted = fsoReference(pixel).attachments[0].r;
  EXPECT_GT(weighted, 0.5f + 0.05f) << "farther samples weigh more";
  EXPECT_NEAR(out_[0][0].r, weighted, 1e-3f);
}

TEST(FsoCompressedPosition, EveryMethodRendersAsWithTheKneeEncoding) {
  // The FSO-shaped host storing position z as FreeSpace Open does today: every method runs on it, and
  // its images match those of the host's own encoding (both keep ~5e-4 relative depth precision here,
  // so only a few pixels whose depth tests sit on a rounding step may differ).
  host::Scene knee = host::loadScene("default");
  host::Scene fso = knee;
  fso.positionDepth = host::PositionDepth::FsoCompressed;
  PatchedHost kneeHost(knee, 96, 72), fsoHost(fso, 96, 72);
  std::vector<std::string> specs = {"resolve/fso", "resolve/window"};
  for (const retroaa::MethodInfo& row : retroaa::methodTable()) specs.push_back(row.name);
  for (const std::string& spec : specs) {
    const app::DisplayImage a = kneeHost.render(spec), b = fsoHost.render(spec);
    const app::ErrorMetrics difference = app::compare(b, a, {});
    EXPECT_GT(difference.psnrDb, 35.0) << spec;
    std::printf("%-14s %.1f dB between the encodings\n", spec.c_str(), difference.psnrDb);
    EXPECT_TRUE(fsoHost.hooks->lastError().empty()) << spec << ": " << fsoHost.hooks->lastError();
  }
}
