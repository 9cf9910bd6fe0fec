// `aggregate` (Crassin et al., "Aggregate G-Buffer Anti-Aliasing", 2016) retrofitted: clustering and
// aggregate attributes are computed from the MSAA G-buffer, and each aggregate is a slice the host's
// unchanged lighting lights once, composited by the share of the pixel's samples it holds.
#include <cmath>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

class AggregateTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<AggregateTechnique>();
    AggregateTechnique& t = *technique;
    const GBufferLayout& layout = context.layout;
    const MsaaGBuffer& source = *shared.msaa;
    t.stencilExport_ = context.capabilities.stencilExport;
    t.aggregateCount_ = context.config.aggregateCount;
    t.samples_ = source.samples();
    auto cluster = context.shaders->program(
        "common/fullscreen.vert", "aggregate/cluster.frag",
        source.shaderDefines(layout, false) + defineLine("MAX_AGGREGATES", std::min(t.aggregateCount_, t.samples_)) +
            defineLine("STENCIL_EXPORT", t.stencilExport_),
        {RETROAA_GBUFFER_PASS_UNIFORMS, "uLength", "uThreshold", "uSamplePositions"});
    if (!cluster) return cluster.error();
    t.clusterProgram_ = std::move(cluster.value());
    for (const bool depth : {false, true}) {  // the G-buffer write, and its host-depth write where the slices make one
      if (depth && !shared.slices->writesHostDepth()) continue;
      auto write = context.shaders->program("common/fullscreen.vert", "aggregate/write_aggregate.frag",
                                            shared.slices->writerDefines(source, layout, depth),
                                            {RETROAA_DEPTH_ENCODING_UNIFORMS, RETROAA_SLICE_DEPTH_UNIFORMS, "uSlice",
                                             "uHasGloss", "uGlossScale", "uGlossBias"});
      if (!write) return write.error();
      (depth ? t.writeDepthProgram_ : t.writeProgram_) = std::move(write.value());
    }
    auto composite = context.shaders->program("common/fullscreen.vert", "aggregate/composite_coverage.frag", "",
                                              {"uSlice", "uSamples", "uSliceLight"});
    if (!composite) return composite.error();
    t.compositeProgram_ = std::move(composite.value());

    t.assignment_ = makeTexture(context, GL_RG32UI, layout.width, layout.height, 0, "aggregate.assignment", t.bytes_);
    t.clusterTarget_ = makeFramebuffer(context, "aggregate.cluster");
    const GLuint fbo = t.clusterTarget_.get();
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, shared.slices->counts(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, t.assignment_.get(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_STENCIL_ATTACHMENT, shared.slices->mask(), 0);
    const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo, 2, drawBuffers);
    if (Status status = checkFramebuffer(fbo, "aggregate.cluster"); !status) return status.error();

    t.samplePositions_ = source.samplePositions();
    return std::unique_ptr<Technique>(std::move(technique));
  }

  // Algorithm 1: the slice count (aggregates + background) and every sample's aggregate.
  Status afterResolve(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "aggregate.cluster");
    shared.msaa->beginPass(clusterProgram_, context, frame);
    clusterProgram_.set("uLength", context.config.aggregateLength);
    clusterProgram_.set("uThreshold", context.config.aggregateThreshold);
    clusterProgram_.setVec2Array("uSamplePositions", samples_, samplePositions_.data());
    return shared.slices->writeMask(context, clusterProgram_.get(), stencilExport_, clusterTarget_.get());
  }

  SliceRenderer::Plan slicePlan(PluginContext& context, SharedTargets&) override {
    SliceRenderer::Plan plan;
    plan.firstSliceEverywhere = true;  // aggregate 0 replaces the resolved value where it differs
    plan.sliceCount = std::min(aggregateCount_, samples_) + 1;  // + background
    plan.writeProgram = &writeProgram_;
    plan.writeDepthProgram = &writeDepthProgram_;
    plan.bindWriteInputs = [this, &context](const ShaderProgram& program) {
      const GBufferLayout& layout = context.layout;
      glBindTextureUnit(kUnitSliceWeights, assignment_.get());
      program.setDepthEncoding(context);
      program.set("uHasGloss", layout.glossEncoding.present ? 1 : 0);
      program.set("uGlossScale", layout.glossEncoding.log2ExponentScale);
      program.set("uGlossBias", layout.glossEncoding.log2ExponentBias);
    };
    plan.compositeProgram = &compositeProgram_;
    plan.bindCompositeInputs = [this]() {
      glBindTextureUnit(kUnitSliceWeights, assignment_.get());
      compositeProgram_.set("uSamples", samples_);
    };
    return plan;
  }

  uint64_t bytes() const override { return bytes_; }
  bool keepsObjectsFor(const Config& config) const override { return config.aggregateCount == aggregateCount_; }

 private:
  ShaderProgram clusterProgram_, writeProgram_, writeDepthProgram_, compositeProgram_;
  GlTexture assignment_;
  GlFramebuffer clusterTarget_;
  std::vector<float> samplePositions_;
  int aggregateCount_ = 0;
  int samples_ = 1;
  bool stencilExport_ = false;
  uint64_t bytes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Technique>> createAggregateTechnique(PluginContext& context, SharedTargets& shared) {
  return AggregateTechnique::create(context, shared);
}

// The config keys of `aggregate` (its registry row lists them: registry.cpp).
std::vector<Key> aggregateKeys() {
  return {
      integer("aggregate_count", &Config::aggregateCount, 1, 4,
              "at most this many aggregates per pixel (plus background); more is closer to per-sample"),
      number("aggregate_threshold", &Config::aggregateThreshold, 0, 10,
             "t, the distance beyond which a sample seeds a new aggregate; 0 splits every distinct sample"),
      number("aggregate_length", &Config::aggregateLength, 0.01f, 1000,
             "k, the characteristic length in pixel footprints; smaller splits at smaller depth gaps"),
  };
}

}  // namespace retroaa
