// `edge` (Thibieroz) and `per-sample`: the per-pixel slice count from an edge detector; per-sample's
// detector marks every pixel. The slices light N samples where the count is N, with weights 1 / N.
#include <cmath>
#include <string>

#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

EdgeDetector detectorFor(const Config& config) {
  return config.method == Method::PerSample ? EdgeDetector::EveryPixel : config.edgeDetector;
}

class EdgeTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<EdgeTechnique>();
    technique->detector_ = detectorFor(context.config);
    technique->stencilExport_ = context.capabilities.stencilExport;
    const std::string defines = shared.msaa->shaderDefines(context.layout, false) +
                                defineLine("EDGE_DETECTOR", int(technique->detector_)) +
                                defineLine("STENCIL_EXPORT", technique->stencilExport_);
    auto program = context.shaders->program("common/fullscreen.vert", "edge/detect_edges.frag", defines,
                                            {RETROAA_GBUFFER_PASS_UNIFORMS, "uDepthCloseness", "uNormalCosine"});
    if (!program) return program.error();
    technique->program_ = std::move(program.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status afterResolve(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "edge_mask");
    shared.msaa->beginPass(program_, context, frame);
    // A budget scale above 1 marks more pixels: a smaller closeness.
    program_.set("uDepthCloseness", context.config.edgeDepthCloseness / float(context.budgetScale));
    program_.set("uNormalCosine", std::cos(context.config.edgeNormalAngleDegrees * 3.14159265f / 180.0f));
    return shared.slices->writeMask(context, program_.get(), stencilExport_);
  }

  // The depth detector's closeness trades time for quality continuously.
  bool followsBudget(const Config& config) const override {
    return config.method == Method::Edge && config.edgeDetector == EdgeDetector::Depth;
  }
  bool keepsObjectsFor(const Config& config) const override { return detectorFor(config) == detector_; }

 private:
  ShaderProgram program_;
  EdgeDetector detector_ = EdgeDetector::Coverage;
  bool stencilExport_ = false;
};

}  // namespace

Result<std::unique_ptr<Technique>> createEdgeTechnique(PluginContext& context, SharedTargets& shared) {
  return EdgeTechnique::create(context, shared);
}

}  // namespace retroaa
