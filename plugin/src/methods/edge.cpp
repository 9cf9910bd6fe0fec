// `edge` (Thibieroz), `per-sample` and `ssaa`: the per-pixel slice count from an edge detector; per-sample's
// and ssaa's detector marks every pixel. The slices light N samples where the count is N, with weights 1 / N.
// `ssaa` is ordered-grid supersampling, the reference of Holländer et al.'s Table 1: every sub-position of
// an m×m supersampled G-buffer (the grant raises `supersample` 0 to 2), lit in the Bayer order
// (pipeline.h's sampleOrder), so that a sliced method forced to m² samples in that order composites the
// same lights in the same order and equals it bit for bit.
#include <cmath>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

EdgeDetector detectorFor(const Config& config) {
  return config.method == Method::PerSample || config.method == Method::Ssaa ? EdgeDetector::EveryPixel
                                                                             : config.edgeDetector;
}

class EdgeTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<EdgeTechnique>();
    technique->detector_ = detectorFor(context.config);
    technique->stencilExport_ = context.capabilities.stencilExport;
    // The detector's own pass, for a frame the resolve does not count (a compute resolve); every pixel's
    // count is a clear and needs none.
    if (technique->detector_ != EdgeDetector::EveryPixel) {
      const std::string defines = shared.msaa->shaderDefines(context.layout, false) +
                                  defineLine("EDGE_DETECTOR", int(technique->detector_)) +
                                  defineLine("STENCIL_EXPORT", technique->stencilExport_);
      auto program = context.shaders->program("common/fullscreen.vert", "edge/detect_edges.frag", defines,
                                              {RETROAA_GBUFFER_PASS_UNIFORMS, "uDepthCloseness", "uNormalCosine"});
      if (!program) return program.error();
      technique->program_ = std::move(program.value());
    }
    if (context.config.method == Method::Ssaa) technique->order_ = sampleOrder(*shared.msaa);
    return std::unique_ptr<Technique>(std::move(technique));
  }

  // The detectors run inside the resolve, on the samples it fetches anyway; per-sample's and ssaa's count
  // is every sample everywhere, which needs no pass at all.
  std::optional<ResolveCounts> resolveCounts(PluginContext& context, SharedTargets& shared) override {
    if (detector_ == EdgeDetector::EveryPixel) return std::nullopt;
    return ResolveCounts{detector_, depthCloseness(context), normalCosine(context), shared.slices->counts()};
  }

  Status afterResolve(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "edge_mask");
    if (detector_ == EdgeDetector::EveryPixel) {
      shared.slices->writeUniformMask(context, shared.msaa->samples());
      return Status::ok();
    }
    if (shared.resolve->wroteCounts()) return shared.slices->writeStencilFromCounts(context);
    // The compute resolve writes no counts: the detector's own pass.
    shared.msaa->beginPass(program_, context, frame);
    program_.set("uDepthCloseness", depthCloseness(context));
    program_.set("uNormalCosine", normalCosine(context));
    return shared.slices->writeMask(context, program_.get(), stencilExport_);
  }

  SliceRenderer::Plan slicePlan(PluginContext&, SharedTargets&) override {
    SliceRenderer::Plan plan;
    plan.sampleOrder = order_;
    plan.firstSliceEverywhere = !order_.empty();  // ssaa: every pixel's first slice, in sample order
    return plan;
  }

  // The depth detector's closeness trades time for quality continuously.
  bool followsBudget(const Config& config) const override {
    return config.method == Method::Edge && config.edgeDetector == EdgeDetector::Depth;
  }
  bool keepsObjectsFor(const Config& config) const override { return detectorFor(config) == detector_; }

 private:
  // A budget scale above 1 marks more pixels: a smaller closeness.
  static float depthCloseness(const PluginContext& context) {
    return context.config.edgeDepthCloseness / float(context.budgetScale);
  }
  static float normalCosine(const PluginContext& context) {
    return std::cos(context.config.edgeNormalAngleDegrees * 3.14159265f / 180.0f);
  }

  ShaderProgram program_;
  EdgeDetector detector_ = EdgeDetector::Coverage;
  std::vector<int> order_;  // ssaa's Bayer order; empty: samples in index order
  bool stencilExport_ = false;
};

}  // namespace

Result<std::unique_ptr<Technique>> createEdgeTechnique(PluginContext& context, SharedTargets& shared) {
  return EdgeTechnique::create(context, shared);
}

// The config keys of `edge` (its registry row lists them: registry.cpp).
std::vector<Key> edgeKeys() {
  return {
      named("edge_detector", &Config::edgeDetector, kEdgeDetectors,
            "how `edge` finds pixels to light per sample; changing it rebuilds the detector (its program)"),
      number("edge_depth_closeness", &Config::edgeDepthCloseness, 0, 100,
             "c of the depth detector; smaller marks more pixels (slower, closer to per-sample)"),
      number("edge_normal_angle_deg", &Config::edgeNormalAngleDegrees, 0, 180,
             "angle of the normal detector; smaller marks more pixels"),
  };
}

}  // namespace retroaa
