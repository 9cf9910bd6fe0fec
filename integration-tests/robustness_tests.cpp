// The hard-case matrix: every lighting-stage method × every hard case, at N = 2 and 4, lit by the
// host's real lighting (ambient, a directional light, a point light exactly on the surface). Every
// output value must be finite and non-negative, and no method may be further from the per-sample
// reference than `off` is by more than a stated margin. With RETROAA_ROBUSTNESS_TABLE set, the matrix
// is written there as Markdown (make docs-robustness → docs/robustness.md).
#include "commands.h"
#include "test_support.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>

using namespace testing_support;

namespace {

constexpr int kWidth = 16, kHeight = 8;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kMarginRms = 0.02;  // allowed extra RMS error (linear radiance) over `off`

// Known violations of the margin, documented in docs/robustness.md; the test checks they still fail,
// so this list cannot go stale. `back` lights a grazing pixel at its farthest samples' mean position;
// with a light on the surface that is far off.
// On the grazing plane a point light sits exactly at the surface point. `back` lights only the
// farthest samples; `window` weighs the samples unevenly (2 footprints: full, 4: a tenth), so the
// averaged position lands a fraction of a footprint from the light and lights far brighter than any
// sample. Both are what those weightings compute; the table keeps them visible.
bool knownWorseThanOff(const std::string& method, const std::string& hardCase) {
  return (method == "resolve/back" || method == "resolve/window") && hardCase == "grazing plane";
}

struct HardCase {
  const char* name;
  std::vector<SyntheticSample> samples;  // per pixel, the same in every pixel
};

std::vector<HardCase> hardCases() {
  SyntheticSample nanSample = surfaceSample(10), infSample = surfaceSample(10);
  for (glm::vec4& a : nanSample.attachments) a = glm::vec4(kNaN);
  infSample.attachments[1].x = kInf;
  const float footprint = 10.0f * std::tan(1.0f / kWidth);
  SyntheticSample red = surfaceSample(10, {0, 0, 1}, {0.9f, 0.1f, 0.1f}),
                  blue = surfaceSample(10, {0, 0, 1}, {0.1f, 0.1f, 0.9f});
  return {
      {"all background", {backgroundSample(), backgroundSample(), backgroundSample(), backgroundSample()}},
      {"NaN sample", {surfaceSample(10), nanSample, surfaceSample(10), surfaceSample(10)}},
      {"Inf position", {surfaceSample(10), surfaceSample(10), infSample, surfaceSample(10)}},
      {"zero-length normals",
       {surfaceSample(10, glm::vec3(0)), surfaceSample(10, glm::vec3(0)), surfaceSample(10, glm::vec3(0)),
        surfaceSample(10, glm::vec3(0))}},
      {"0.1 m and 1e6 m", {surfaceSample(0.1f), surfaceSample(0.1f), surfaceSample(1e6f), surfaceSample(1e6f)}},
      {"grazing plane",
       {surfaceSample(10 - 3 * footprint), surfaceSample(10 - footprint), surfaceSample(10 + footprint),
        surfaceSample(10 + 3 * footprint)}},
      {"z-fighting plates", {red, blue, red, blue}},
      {"sub-pixel wire", {surfaceSample(3), backgroundSample(), backgroundSample(), backgroundSample()}},
      {"light on the surface",
       {surfaceSample(10, glm::normalize(glm::vec3(0.3f, 0, 1))), surfaceSample(10), surfaceSample(10.001f),
        surfaceSample(10)}},
  };
}

struct Cell {
  bool finite = true, nonNegative = true;
  double rms = 0;
};

}  // namespace

TEST(Robustness, EveryMethodOnEveryHardCaseIsFiniteAndNoWorseThanOff) {
  // Ambient, a directional light and a point light exactly at the surface point (view (0.1, -0.2, -10)).
  SyntheticFrame frame(kWidth, kHeight);
  frame.scene = host::parseScene(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
    "materials": [{"name": "m"}], "objects": [], "ambient": [0.05, 0.05, 0.05],
    "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 0.8},
               {"type": "point", "position": [0.1, -0.2, -5.0], "radius": 5, "intensity": 10}]})",
                                 "hard cases", ".");
  frame.renderer = std::make_unique<host::Renderer>(frame.scene, kWidth, kHeight);
  const host::Camera camera = frame.scene.camera;
  const std::vector<std::string> methods = {
      "off",         "resolve",        "resolve/front", "resolve/back",
      "resolve/fso", "resolve/window", "resolve/mean",  "resolve+reconstruct@reconstruct_before_tonemap=on",
      "edge",        "adaptive",       "aggregate",     "smaa-s2x",
      "per-sample"};
  std::map<std::string, std::map<std::string, Cell>> matrix[2];
  const int sampleCounts[] = {2, 4};
  for (int n = 0; n < 2; ++n)
    for (const HardCase& hardCase : hardCases()) {
      const std::vector<std::vector<SyntheticSample>> pixels(kWidth * kHeight, hardCase.samples);
      auto light = [&](const std::string& method) {
        retroaa::Config config = app::parseMethodSpec(method, {}).config;
        config.samples = sampleCounts[n];
        auto hooks = frame.attach(config);
        if (!hooks) throw std::runtime_error("the patch did not attach");
        retroaa::Plugin& plugin = hooks->plugin();
        fillGeometry(plugin, kWidth, kHeight, pixels);
        EXPECT_TRUE(plugin.resolve({verticalFovFor(1.0f, kWidth, kHeight), 0.1f, 1000.0f}));
        EXPECT_TRUE(plugin.shade([&](GLuint target) { frame.renderer->lightGBuffer(camera, target); }));
        return frame.read(frame.renderer->targets().lightTexture);
      };
      const std::vector<glm::vec4> reference = light("per-sample");
      for (const std::string& method : methods) {
        const std::vector<glm::vec4> result = light(method);
        Cell cell;
        double sum = 0;
        for (size_t i = 0; i < result.size(); ++i)
          for (int c = 0; c < 3; ++c) {
            cell.finite = cell.finite && std::isfinite(result[i][c]);
            cell.nonNegative = cell.nonNegative && !(result[i][c] < 0.0f);
            const double d = double(result[i][c]) - (std::isfinite(reference[i][c]) ? reference[i][c] : 0.0f);
            sum += d * d;
          }
        cell.rms = std::sqrt(sum / (3.0 * result.size()));
        matrix[n][hardCase.name][method] = cell;
      }
    }

  std::ostringstream table;
  for (int n = 0; n < 2; ++n) {
    table << "\n### N = " << sampleCounts[n] << " requested (" << (sampleCounts[n] == 2 ? "llvmpipe allocates 4" : "4")
          << ")\n\n| hard case |";
    for (const std::string& m : methods) table << " `" << m << "` |";
    table << "\n|---|";
    for (size_t i = 0; i < methods.size(); ++i) table << "---|";
    table << "\n";
    for (const HardCase& hardCase : hardCases()) {
      table << "| " << hardCase.name << " |";
      const double off = matrix[n][hardCase.name]["off"].rms;
      for (const std::string& m : methods) {
        const Cell& cell = matrix[n][hardCase.name][m];
        const bool withinMargin = cell.rms <= off + kMarginRms;
        const bool known = knownWorseThanOff(m, hardCase.name);
        char text[64];
        std::snprintf(text, sizeof text, " %s %.3f |",
                      !(cell.finite && cell.nonNegative) ? "**FAIL**"
                      : withinMargin                     ? "ok"
                      : known                            ? "worse (known)"
                                                         : "**FAIL**",
                      cell.rms);
        table << text;
        EXPECT_TRUE(cell.finite) << m << " / " << hardCase.name << " at N=" << sampleCounts[n];
        EXPECT_TRUE(cell.nonNegative) << m << " / " << hardCase.name << " at N=" << sampleCounts[n];
        EXPECT_EQ(withinMargin, !known) << m << " / " << hardCase.name << " at N=" << sampleCounts[n] << ": RMS "
                                        << cell.rms << " against off's " << off;
      }
      table << "\n";
    }
  }
  std::printf("%s", table.str().c_str());
  if (const char* path = std::getenv("RETROAA_ROBUSTNESS_TABLE")) std::ofstream(path) << table.str();
}
