// `adaptive` (Holländer et al., JCGT 2013) through slices: k samples where the metrics ask for them.
#include <cmath>
#include <limits>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

std::vector<int> spreadingSampleOrder(const std::vector<float>& positionsXY) {
  const int n = int(positionsXY.size() / 2);
  std::vector<int> order;
  std::vector<bool> taken(n, false);
  auto distance2 = [&](int a, float x, float y) {
    const float dx = positionsXY[2 * a] - x, dy = positionsXY[2 * a + 1] - y;
    return dx * dx + dy * dy;
  };
  while (int(order.size()) < n) {
    int best = -1;
    float bestScore = -1.0f;
    for (int candidate = 0; candidate < n; ++candidate) {
      if (taken[candidate]) continue;
      // First: nearest the centre. Then: farthest from every sample already taken.
      float score;
      if (order.empty()) {
        score = -distance2(candidate, 0.5f, 0.5f);
      } else {
        score = std::numeric_limits<float>::max();
        for (int t : order) score = std::min(score, distance2(candidate, positionsXY[2 * t], positionsXY[2 * t + 1]));
      }
      if (best < 0 || score > bestScore) best = candidate, bestScore = score;
    }
    taken[best] = true;
    order.push_back(best);
  }
  return order;
}

std::vector<int> bayerSampleOrder(int m) {
  static const int kBayer2[4] = {0, 2, 3, 1};
  static const int kBayer4[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
  const int* matrix = m == 2 ? kBayer2 : m == 4 ? kBayer4 : nullptr;
  if (!matrix) return spreadingSampleOrder(orderedGridPositions(m));
  std::vector<int> order(size_t(m) * m);
  for (int s = 0; s < m * m; ++s) order[size_t(matrix[s])] = s;
  return order;
}

std::vector<int> sampleOrder(const MsaaGBuffer& source) {
  return source.supersample() > 1 ? bayerSampleOrder(source.supersample())
                                  : spreadingSampleOrder(source.samplePositions());
}

namespace {

class AdaptiveTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<AdaptiveTechnique>();
    AdaptiveTechnique& t = *technique;
    const GBufferLayout& layout = context.layout;
    const MsaaGBuffer& source = *shared.msaa;
    t.stencilExport_ = context.capabilities.stencilExport;
    auto geometry = context.shaders->program(
        "common/fullscreen.vert", "adaptive/geometry_metric.frag", source.shaderDefines(layout, false),
        {RETROAA_GBUFFER_PASS_UNIFORMS, "uDepthScale", "uNormalScale", "uShadingScale", "uThresholdMin",
         "uThresholdEdge", "uFirstSample", "uSampleOffsets", "uImageSize"});
    if (!geometry) return geometry.error();
    t.geometryProgram_ = std::move(geometry.value());
    auto shading = context.shaders->program(
        "common/fullscreen.vert", "adaptive/shading_metric.frag",
        defineLine("SAMPLES", source.samples()) + defineLine("STENCIL_EXPORT", t.stencilExport_),
        {"uShadingScale", "uTextureScale", "uThresholdMin", "uThresholdEdge", "uMinSamples", "uFirstLight",
         "uGeometryK"});
    if (!shading) return shading.error();
    t.shadingProgram_ = std::move(shading.value());
    t.geometryK_ = makeTexture(context, GL_RGBA16F, layout.width, layout.height, 0, "adaptive.geometry_k", t.bytes_);
    t.geometryTarget_ = makeFramebuffer(context, "adaptive.geometry_k");
    glNamedFramebufferTexture(t.geometryTarget_.get(), GL_COLOR_ATTACHMENT0, t.geometryK_.get(), 0);
    if (Status status = checkFramebuffer(t.geometryTarget_.get(), "adaptive.geometry_k"); !status)
      return status.error();

    // The driver's own sample positions decide the order (queried, not assumed); Bayer's on a grid.
    t.order_ = sampleOrder(source);
    // The geometry metric's plane needs each sample's offset from the samples' mean position.
    t.sampleOffsets_ = source.samplePositions();
    const size_t count = t.sampleOffsets_.size() / 2;
    for (int axis = 0; axis < 2; ++axis) {
      float mean = 0.0f;
      for (size_t s = 0; s < count; ++s) mean += t.sampleOffsets_[2 * s + axis] / float(count);
      for (size_t s = 0; s < count; ++s) t.sampleOffsets_[2 * s + axis] -= mean;
    }
    return std::unique_ptr<Technique>(std::move(technique));
  }

  // The geometry metric, after the model pass.
  Status afterResolve(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "adaptive.geometry_metric");
    context.beginFullscreenPass(geometryTarget_.get());
    shared.msaa->beginPass(geometryProgram_, context, frame);
    const float budget = float(context.budgetScale);  // 1 without a budget
    geometryProgram_.set("uDepthScale", context.config.adaptiveDepthScale * budget);
    geometryProgram_.set("uNormalScale", context.config.adaptiveNormalScale * budget);
    geometryProgram_.set("uShadingScale", context.config.adaptiveShadingScale * budget);
    geometryProgram_.set("uThresholdMin", context.config.adaptiveThresholdMin);
    geometryProgram_.set("uThresholdEdge", context.config.adaptiveThresholdEdge);
    geometryProgram_.set("uFirstSample", order_.front());
    geometryProgram_.setVec2Array("uSampleOffsets", int(sampleOffsets_.size() / 2), sampleOffsets_.data());
    geometryProgram_.set("uImageSize", float(context.layout.width), float(context.layout.height));
    context.drawFullscreen();
    return Status::ok();
  }

  // The shading metric on the lit first sample writes the counts (Holländer et al. light one sample
  // of every pixel first).
  SliceRenderer::Plan slicePlan(PluginContext& context, SharedTargets& shared) override {
    SliceRenderer::Plan plan;
    plan.sampleOrder = order_;
    plan.firstSliceEverywhere = true;
    SliceRenderer& slices = *shared.slices;
    plan.maskAfterFirstSlice = [this, &context, &slices]() {
      ScopedPass timed(context, "adaptive.shading_metric");
      shadingProgram_.use();
      shadingProgram_.bindTexture("uFirstLight", slices.firstSliceLight());
      shadingProgram_.bindTexture("uGeometryK", geometryK_.get());
      shadingProgram_.set("uShadingScale", context.config.adaptiveShadingScale * float(context.budgetScale));
      shadingProgram_.set("uTextureScale", context.config.adaptiveTextureScale * float(context.budgetScale));
      shadingProgram_.set("uThresholdMin", context.config.adaptiveThresholdMin);
      shadingProgram_.set("uThresholdEdge", context.config.adaptiveThresholdEdge);
      shadingProgram_.set("uMinSamples", context.config.adaptiveMinSamples);
      return slices.writeMask(context, shadingProgram_.get(), stencilExport_);
    };
    return plan;
  }

  bool followsBudget(const Config&) const override { return true; }
  uint64_t bytes() const override { return bytes_; }
  bool keepsObjectsFor(const Config&) const override { return true; }  // settings are uniforms

 private:
  ShaderProgram geometryProgram_, shadingProgram_;
  GlTexture geometryK_;
  GlFramebuffer geometryTarget_;
  std::vector<int> order_;
  std::vector<float> sampleOffsets_;
  bool stencilExport_ = false;
  uint64_t bytes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Technique>> createAdaptiveTechnique(PluginContext& context, SharedTargets& shared) {
  return AdaptiveTechnique::create(context, shared);
}

// The config keys of `adaptive` (its registry row lists them: registry.cpp).
std::vector<Key> adaptiveKeys() {
  return {
      number("adaptive_depth_scale", &Config::adaptiveDepthScale, 0, 1000,
             "k_d per unit of depth variance (in pixel footprints²); larger refines more"),
      number("adaptive_normal_scale", &Config::adaptiveNormalScale, 0, 1000,
             "k_n per unit of normal-cone width sqrt(1 - min|n·n_i|); larger refines more"),
      number("adaptive_shading_scale", &Config::adaptiveShadingScale, 0, 1000,
             "k_s = scale * N * luma range of the first lit sample; larger refines more"),
      number("adaptive_texture_scale", &Config::adaptiveTextureScale, 0, 1000,
             "k_t = scale * N * luma range of the first lit sample scaled by the albedo over the pixel "
             "(texture detail inside it); larger refines more"),
      number("adaptive_threshold_min", &Config::adaptiveThresholdMin, 0, 1,
             "luma ranges below this never refine (FXAA's absolute threshold)"),
      number("adaptive_threshold_edge", &Config::adaptiveThresholdEdge, 0, 1,
             "luma ranges below this fraction of the local maximum never refine"),
      integer("adaptive_min_samples", &Config::adaptiveMinSamples, 1, 16,
              "floor of the per-pixel sample count; N lights every sample"),
  };
}

}  // namespace retroaa
