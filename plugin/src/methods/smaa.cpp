// `smaa` (SMAA 1x after tonemapping, as a method or stacked: `resolve+smaa`) and `smaa-s2x` (SMAA 1x on
// two single-sample slices of the MSAA G-buffer, each lit by the host, blended 50/50): Jimenez,
// Echevarria, Sousa, Gutierrez, "SMAA: Enhanced Subpixel Morphological Antialiasing", Eurographics
// 2012. Three passes (shaders/smaa/): edges, blending weights (area and search lookup textures,
// generated at build time by plugin/tools/smaa_lookup_tables.cpp), neighbourhood blending.
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "smaa.h"

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

// SMAA's subsample indices (methods.h).
// The rows hold orthogonal offsets {0, −¼, ¼, −⅛, ⅛, −⅜, ⅜} and diagonal ones {0, (¼, −¼), (−¼, ¼),
// (⅛, −⅛), (−⅛, ⅛)}; the nearest of each is taken. Orthogonal offsets are the sample's offset from the
// centre, negated (the reference's convention: its S2x sample at (+¼, +¼) reads rows 1, 1 and diagonal
// row 1); the shaders' mirrored frame (y up) needs no other change.
std::array<float, 4> smaaSubsampleIndices(float x, float y) {
  static const float ortho[7] = {0.0f, -0.25f, 0.25f, -0.125f, 0.125f, -0.375f, 0.375f};
  static const float diag[5][2] = {{0, 0}, {0.25f, -0.25f}, {-0.25f, 0.25f}, {0.125f, -0.125f}, {-0.125f, 0.125f}};
  const float dx = x - 0.5f, dy = y - 0.5f;
  auto nearestOrtho = [&](float offset) {
    int best = 0;
    for (int i = 1; i < 7; ++i)
      if (std::abs(ortho[i] - offset) < std::abs(ortho[best] - offset)) best = i;
    return float(best);
  };
  int bestDiag = 0;
  float bestDistance = 1e9f;
  for (int i = 0; i < 5; ++i) {
    const float distance = std::hypot(diag[i][0] - dx, diag[i][1] + dy);
    if (distance < bestDistance) bestDistance = distance, bestDiag = i;
  }
  return {nearestOrtho(-dx), nearestOrtho(-dy), float(bestDiag), 0.0f};
}

std::array<int, 2> smaaS2xSamplePair(const std::vector<float>& positionsXY) {
  const int count = int(positionsXY.size() / 2);
  std::array<int, 2> best{0, std::min(1, count - 1)};
  double bestOffCentre = 1e9, bestSeparation = -1;
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b) {
      const double ax = positionsXY[2 * a], ay = positionsXY[2 * a + 1];
      const double bx = positionsXY[2 * b], by = positionsXY[2 * b + 1];
      const double offCentre = std::hypot((ax + bx) / 2 - 0.5, (ay + by) / 2 - 0.5);
      const double separation = std::hypot(ax - bx, ay - by);
      // Centred first (an average of two samples off the centre shifts the image), then spread.
      if (offCentre < bestOffCentre - 1e-6 ||
          (offCentre < bestOffCentre + 1e-6 && separation > bestSeparation + 1e-6)) {
        best = {a, b};
        bestOffCentre = offCentre;
        bestSeparation = separation;
      }
    }
  return best;
}

namespace {

#include "smaa_lookup_tables.inc"

struct SmaaPreset {
  float threshold;
  int searchSteps, diagonalSteps, cornerRounding;
};

// The reference's presets (SMAA_PRESET_LOW … ULTRA).
SmaaPreset presetFor(SmaaQuality quality) {
  switch (quality) {
    case SmaaQuality::Low: return {0.15f, 4, 0, 100};
    case SmaaQuality::Medium: return {0.1f, 8, 0, 100};
    case SmaaQuality::High: return {0.1f, 16, 8, 25};
    case SmaaQuality::Ultra: return {0.05f, 32, 16, 25};
  }
  return {0.1f, 16, 8, 25};
}

// SMAA's three passes and what they hold, for one kind of input: the tonemapped display (sRGB-encoded)
// or, for S2x, a slice's linear HDR light.
class SmaaPasses {
 public:
  // `displayEncoding`: PostTarget::encodingDefine() for the display; empty for HDR input. `blendedInPlace`:
  // the texture the blend rewrites in place, only where a pixel or the neighbours it blends with hold
  // weights (MarkedRewrite), reading a copy as `input`; 0: the blend writes every pixel where run() binds.
  static Result<SmaaPasses> create(PluginContext& context, bool hdrInput, const std::string& displayEncoding,
                                   const char* label, GLuint blendedInPlace) {
    SmaaPasses p;
    const GBufferLayout& layout = context.layout;
    p.quality_ = context.config.smaaQuality;
    p.detection_ = context.config.smaaEdgeDetection;
    p.positionAttachment_ = findRole(layout, AttachmentRole::ViewPosition);
    const std::string name = label;
    p.edges_ = makeTexture(context, GL_RG8, layout.width, layout.height, 0, (name + ".edges").c_str(), p.bytes_);
    p.weights_ = makeTexture(context, GL_RGBA8, layout.width, layout.height, 0, (name + ".weights").c_str(), p.bytes_);
    p.area_ = makeTexture(context, GL_RG8, kSmaaAreaWidth, kSmaaAreaHeight, 0, (name + ".area").c_str(), p.bytes_);
    // The weights pass reads two edges per bilinear fetch, and interpolates the area texture's distances.
    for (GLuint texture : {p.edges_.get(), p.area_.get()}) {
      glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    p.search_ =
        makeTexture(context, GL_R8UI, kSmaaSearchWidth, kSmaaSearchHeight, 0, (name + ".search").c_str(), p.bytes_);
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // the search texture's rows are 66 bytes
    glTextureSubImage2D(p.area_.get(), 0, 0, 0, kSmaaAreaWidth, kSmaaAreaHeight, GL_RG, GL_UNSIGNED_BYTE,
                        kSmaaAreaTexture);
    glTextureSubImage2D(p.search_.get(), 0, 0, 0, kSmaaSearchWidth, kSmaaSearchHeight, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                        kSmaaSearchTexture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);

    // The reference's optimisation (SMAA.hlsl, integration step 9): the edges pass marks its edge pixels in
    // a stencil, and the weights pass, whose searches are the technique's cost, runs only where it is set.
    p.edgePixels_ = makeTexture(context, GL_STENCIL_INDEX8, layout.width, layout.height, 0,
                                (name + ".edge_pixels").c_str(), p.bytes_);
    p.edgesTarget_ = makeFramebuffer(context, (name + ".edges").c_str());
    glNamedFramebufferTexture(p.edgesTarget_.get(), GL_COLOR_ATTACHMENT0, p.edges_.get(), 0);
    p.weightsTarget_ = makeFramebuffer(context, (name + ".weights").c_str());
    glNamedFramebufferTexture(p.weightsTarget_.get(), GL_COLOR_ATTACHMENT0, p.weights_.get(), 0);
    for (GLuint fbo : {p.edgesTarget_.get(), p.weightsTarget_.get()}) {
      glNamedFramebufferTexture(fbo, GL_STENCIL_ATTACHMENT, p.edgePixels_.get(), 0);
      if (Status status = checkFramebuffer(fbo, label); !status) return status.error();
    }

    const SmaaPreset preset = presetFor(p.quality_);
    char threshold[48];
    std::snprintf(threshold, sizeof threshold, "#define SMAA_THRESHOLD %.9g\n", double(preset.threshold));
    const std::string common = defineLine("SMAA_HDR_INPUT", hdrInput) + displayEncoding;
    const bool depth = p.detection_ == SmaaEdgeDetection::Depth;
    const std::string edgeDefines = common + threshold + defineLine("SMAA_EDGE_MODE", int(p.detection_)) +
                                    (depth ? depthEncodingDefines(layout) : std::string());
    auto edges = depth ? context.shaders->program("common/fullscreen.vert", "smaa/edges.frag", edgeDefines,
                                                  {"uMetrics", "uInput", RETROAA_DEPTH_ENCODING_UNIFORMS})
                       : context.shaders->program("common/fullscreen.vert", "smaa/edges.frag", edgeDefines,
                                                  {"uMetrics", "uInput"});
    if (!edges) return edges.error();
    p.edgesProgram_ = std::move(edges.value());
    auto weights = context.shaders->program("common/fullscreen.vert", "smaa/weights.frag",
                                            common + defineLine("SMAA_MAX_SEARCH_STEPS", preset.searchSteps) +
                                                defineLine("SMAA_MAX_SEARCH_STEPS_DIAG", preset.diagonalSteps) +
                                                defineLine("SMAA_CORNER_ROUNDING", preset.cornerRounding),
                                            {"uMetrics", "uSubsampleIndices", "uEdges", "uArea", "uSearch"});
    if (!weights) return weights.error();
    p.weightsProgram_ = std::move(weights.value());
    for (const bool marking : {false, true}) {
      if (marking && !blendedInPlace) break;
      auto blend =
          context.shaders->program("common/fullscreen.vert", "smaa/blend.frag",
                                   common + defineLine("SMAA_BLEND_MARK", marking), {"uMetrics", "uInput", "uWeights"});
      if (!blend) return blend.error();
      (marking ? p.blendMarkProgram_ : p.blendProgram_) = std::move(blend.value());
    }
    if (blendedInPlace) {
      auto rewrite = MarkedRewrite::create(context, blendedInPlace, name + ".blend", p.bytes_);
      if (!rewrite) return rewrite.error();
      p.blendInPlace_ = std::move(rewrite.value());
    }
    // The size is fixed for the programs' lifetime (a new layout rebuilds every technique).
    const float metrics[4] = {1.0f / layout.width, 1.0f / layout.height, float(layout.width), float(layout.height)};
    for (const ShaderProgram* program : {&p.edgesProgram_, &p.weightsProgram_, &p.blendProgram_, &p.blendMarkProgram_})
      if (program->get()) program->setVec4("uMetrics", metrics);
    return p;
  }

  // SMAA of `input`, written where `bindOutput` binds (with the layout's viewport), or, blended in place,
  // into the texture create() was given (`input` then a copy of it; `bindOutput` unused). `subsample`:
  // the area-texture rows (0 for 1x).
  template <typename BindOutput>
  void run(PluginContext& context, GLuint input, const BindOutput& bindOutput, const float subsample[4]) const {
    const GBufferLayout& layout = context.layout;
    for (GLuint unit : {0u, 1u, 2u}) glBindSampler(unit, 0);  // the textures' own filters
    {
      ScopedPass timed(context, "smaa.edges");
      context.beginFullscreenPass(edgesTarget_.get());
      const GLfloat zero[4] = {0, 0, 0, 0};
      const GLint noEdge = 0;
      glStencilMask(0xFF);  // clears obey the write mask
      // Pixels without edges discard: both start cleared.
      glClearNamedFramebufferfv(edgesTarget_.get(), GL_COLOR, 0, zero);
      glClearNamedFramebufferiv(edgesTarget_.get(), GL_STENCIL, 0, &noEdge);
      glEnable(GL_STENCIL_TEST);  // every pixel the shader keeps is marked
      glStencilFunc(GL_ALWAYS, 1, 0xFF);
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      edgesProgram_.use();
      if (detection_ == SmaaEdgeDetection::Depth) {
        edgesProgram_.setDepthEncoding(context);
        edgesProgram_.bindTexture("uInput", layout.depthSource != DepthSource::PositionChannel
                                                ? layout.depthStencilTexture
                                                : layout.attachments[size_t(positionAttachment_)].texture);
      } else {
        edgesProgram_.bindTexture("uInput", input);
      }
      context.drawFullscreen();
    }
    {
      ScopedPass timed(context, "smaa.weights");
      context.beginFullscreenPass(weightsTarget_.get());
      const GLfloat none[4] = {0, 0, 0, 0};  // what the searches give a pixel without edges
      glClearNamedFramebufferfv(weightsTarget_.get(), GL_COLOR, 0, none);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 1, 0xFF);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      weightsProgram_.use();
      weightsProgram_.bindTexture("uEdges", edges_.get());
      weightsProgram_.bindTexture("uArea", area_.get());
      weightsProgram_.bindTexture("uSearch", search_.get());
      weightsProgram_.setVec4("uSubsampleIndices", subsample);
      context.drawFullscreen();
    }
    {
      ScopedPass timed(context, "smaa.blend");
      const auto bind = [&](const ShaderProgram& program) {
        program.use();
        program.bindTexture("uInput", input);
        program.bindTexture("uWeights", weights_.get());
      };
      if (blendInPlace_) {
        blendInPlace_->run(context, blendMarkProgram_, blendProgram_, bind);
      } else {
        bindOutput();
        bind(blendProgram_);
        context.drawFullscreen();
      }
    }
  }

  bool servesConfig(const Config& config) const {
    return config.smaaQuality == quality_ && config.smaaEdgeDetection == detection_;
  }
  uint64_t bytes() const { return bytes_; }

 private:
  GlTexture edges_, weights_, area_, search_;
  GlTexture edgePixels_;  // stencil: 1 where the edges pass found an edge
  GlFramebuffer edgesTarget_, weightsTarget_;
  ShaderProgram edgesProgram_, weightsProgram_, blendProgram_;
  ShaderProgram blendMarkProgram_;             // blended in place: marks the pixels the blend changes
  std::optional<MarkedRewrite> blendInPlace_;  // none: the blend writes every pixel where run() binds
  SmaaQuality quality_ = SmaaQuality::High;
  SmaaEdgeDetection detection_ = SmaaEdgeDetection::Luma;
  int positionAttachment_ = -1;
  uint64_t bytes_ = 0;
};

// SMAA 1x on the display target, after tonemapping.
class SmaaTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto passes = SmaaPasses::create(context, /*hdrInput=*/false, shared.post->encodingDefine(), "smaa",
                                     shared.post->input(context.layout));
    if (!passes) return passes.error();
    auto technique = std::make_unique<SmaaTechnique>();
    technique->passes_ = std::move(passes.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo&) override {
    static const float kNoSubsample[4] = {0, 0, 0, 0};
    shared.post->copyInputAside(context.layout);  // the blend rewrites the display in place
    passes_.run(
        context, shared.post->copyOfInput(), [] {}, kNoSubsample);
    return Status::ok();
  }

  uint64_t bytes() const override { return passes_.bytes(); }
  bool keepsObjectsFor(const Config& config) const override { return passes_.servesConfig(config); }

 private:
  SmaaPasses passes_;
};

// SMAA S2x: slices 0 and 1 light the two samples of smaaS2xSamplePair in every pixel; SMAA 1x filters each slice's
// light (HDR, before the host's tonemap) with that sample's subsample indices; the composite averages them.
class SmaaS2xTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<SmaaS2xTechnique>();
    SmaaS2xTechnique& t = *technique;
    auto passes = SmaaPasses::create(context, /*hdrInput=*/true, std::string(), "smaa_s2x", 0);
    if (!passes) return passes.error();
    t.passes_ = std::move(passes.value());
    t.stencilExport_ = context.capabilities.stencilExport;
    auto mask = context.shaders->program("common/fullscreen.vert", "smaa/s2x_counts.frag",
                                         defineLine("STENCIL_EXPORT", t.stencilExport_));
    if (!mask) return mask.error();
    t.maskProgram_ = std::move(mask.value());
    const GBufferLayout& layout = context.layout;
    t.filtered_ = makeTexture(context, GL_RGBA16F, layout.width, layout.height, 0, "smaa_s2x.filtered", t.bytes_);
    t.filteredTarget_ = makeFramebuffer(context, "smaa_s2x.filtered");
    glNamedFramebufferTexture(t.filteredTarget_.get(), GL_COLOR_ATTACHMENT0, t.filtered_.get(), 0);
    if (Status status = checkFramebuffer(t.filteredTarget_.get(), "smaa_s2x.filtered"); !status) return status.error();
    const std::vector<float> positions = shared.msaa->samplePositions();
    t.pair_ = smaaS2xSamplePair(positions);
    for (size_t s = 0; s < 2; ++s) {
      const int sample = t.pair_[s];
      t.indices_[s] = smaaSubsampleIndices(positions[2 * sample], positions[2 * sample + 1]);
    }
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status afterResolve(PluginContext& context, SharedTargets& shared, const FrameInfo&) override {
    ScopedPass timed(context, "smaa_s2x.mask");
    return shared.slices->writeMask(context, maskProgram_.get(), stencilExport_);
  }

  SliceRenderer::Plan slicePlan(PluginContext& context, SharedTargets&) override {
    SliceRenderer::Plan plan;
    plan.sampleOrder = {pair_[0], pair_[1]};
    plan.firstSliceEverywhere = true;
    plan.sliceCount = 2;
    plan.filterSliceLight = [this, &context](int slice, GLuint light) -> Result<GLuint> {
      passes_.run(
          context, light, [&] { context.beginFullscreenPass(filteredTarget_.get()); }, indices_[size_t(slice)].data());
      return filtered_.get();
    };
    return plan;
  }

  uint64_t bytes() const override { return bytes_ + passes_.bytes(); }
  bool keepsObjectsFor(const Config& config) const override { return passes_.servesConfig(config); }

 private:
  SmaaPasses passes_;
  ShaderProgram maskProgram_;
  GlTexture filtered_;
  GlFramebuffer filteredTarget_;
  std::array<int, 2> pair_{0, 1};
  std::array<std::array<float, 4>, 2> indices_{};
  bool stencilExport_ = false;
  uint64_t bytes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Technique>> createSmaaTechnique(PluginContext& context, SharedTargets& shared) {
  return SmaaTechnique::create(context, shared);
}
Result<std::unique_ptr<Technique>> createSmaaS2xTechnique(PluginContext& context, SharedTargets& shared) {
  return SmaaS2xTechnique::create(context, shared);
}

// The config keys of `smaa`, `+smaa` and `smaa-s2x` (its registry row lists them: registry.cpp).
std::vector<Key> smaaKeys() {
  return {
      onOff("smaa", &Config::smaa, "SMAA 1x after tonemapping, stacked on the method (before FXAA)"),
      named("smaa_quality", &Config::smaaQuality, kSmaaQualities,
            "SMAA preset: threshold 0.15/0.1/0.1/0.05, search 8/16/32/64 px each way, diagonals and corner "
            "rounding from high on; cost grows with it (FreeSpace Open's -aa_preset 3..6)"),
      named("smaa_edge_detection", &Config::smaaEdgeDetection, kSmaaEdgeDetections,
            "what SMAA finds edges in: luma contrast, per-channel contrast (chroma edges too), or view-depth steps "
            "(geometry only: keeps texture detail, misses shading edges)"),
  };
}

}  // namespace retroaa
