// `ssaa`: ordered-grid supersampling, the reference of Holländer et al.'s Table 1 and a method of its own.
// The G-buffer is m×m supersampled (`supersample` = m; the grant raises 0 to 2); every sub-position of
// every pixel is lit through the slices and box-filtered (weights 1 / m²). The slices light the
// sub-positions in the Bayer order `adaptive` takes them in, so `adaptive` forced to m² samples composites
// the same lights in the same order and equals it bit for bit. Its count mask is edge's every-pixel
// detector (shaders/edge/): no shader of its own.
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

class SsaaTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<SsaaTechnique>();
    const MsaaGBuffer& source = *shared.msaa;
    technique->stencilExport_ = context.capabilities.stencilExport;
    auto program = context.shaders->program("common/fullscreen.vert", "edge/detect_edges.frag",
                                            source.shaderDefines(context.layout, false) +
                                                defineLine("EDGE_DETECTOR", int(EdgeDetector::EveryPixel)) +
                                                defineLine("STENCIL_EXPORT", technique->stencilExport_),
                                            {RETROAA_GBUFFER_PASS_UNIFORMS, "uDepthCloseness", "uNormalCosine"});
    if (!program) return program.error();
    technique->program_ = std::move(program.value());
    technique->order_ = sampleOrder(source);
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status afterResolve(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "ssaa.mask");
    shared.msaa->beginPass(program_, context, frame);
    return shared.slices->writeMask(context, program_.get(), stencilExport_);
  }

  SliceRenderer::Plan slicePlan(PluginContext&, SharedTargets&) override {
    SliceRenderer::Plan plan;
    plan.sampleOrder = order_;
    plan.firstSliceEverywhere = true;
    return plan;
  }

  // A new m reallocates the G-buffer, and every technique with it.
  bool keepsObjectsFor(const Config&) const override { return true; }

 private:
  ShaderProgram program_;
  std::vector<int> order_;
  bool stencilExport_ = false;
};

}  // namespace

Result<std::unique_ptr<Technique>> createSsaaTechnique(PluginContext& context, SharedTargets& shared) {
  return SsaaTechnique::create(context, shared);
}

}  // namespace retroaa
