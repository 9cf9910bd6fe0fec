// `coverage` (Pettineo, "Deferred MSAA"): no lighting per sample; one filter pass after tonemapping
// blends silhouette pixels by the depth sub-samples' coverage (shaders/coverage/). As the method it
// owns a depth-only MSAA prepass target; stacked on a G-buffer method (`coverage_filter=on`) it reads
// the MSAA G-buffer's own depth.
#include <cmath>
#include <string>

#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

bool ownsPrepass(const Config& config) { return config.method == Method::Coverage; }

class CoverageTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<CoverageTechnique>();
    CoverageTechnique& t = *technique;
    const GBufferLayout& layout = context.layout;
    t.ownPrepass_ = ownsPrepass(context.config);
    t.requestedSamples_ = context.config.samples;
    GLuint framebuffer = 0;
    if (!t.ownPrepass_) {
      t.sampleDepth_ = shared.msaa->depthStencil();
      t.samples_ = shared.msaa->samples();
      framebuffer = shared.msaa->framebuffer();
    } else {
      t.depth_ = makeTexture(context, GL_DEPTH24_STENCIL8, layout.width, layout.height,
                             std::max(t.requestedSamples_, 1), "coverage.depth", t.bytes_);
      t.prepass_ = makeFramebuffer(context, "coverage.prepass");
      glNamedFramebufferTexture(t.prepass_.get(), GL_DEPTH_STENCIL_ATTACHMENT, t.depth_.get(), 0);
      glNamedFramebufferDrawBuffer(t.prepass_.get(), GL_NONE);
      if (Status status = checkFramebuffer(t.prepass_.get(), "coverage.prepass"); !status) return status.error();
      glGetTextureLevelParameteriv(t.depth_.get(), 0, GL_TEXTURE_SAMPLES, &t.samples_);
      t.sampleDepth_ = t.depth_.get();
      framebuffer = t.prepass_.get();
    }
    t.samplePositions_.assign(size_t(t.samples_) * 2, 0.5f);
    readSamplePositions(framebuffer, t.samplePositions_);
    const bool logarithmic = layout.depthBufferEncoding == DepthBufferEncoding::Logarithmic;
    auto program =
        context.shaders->program("common/fullscreen.vert", "coverage/coverage_filter.frag",
                                 defineLine("SAMPLES", t.samples_) + defineLine("LOGARITHMIC_DEPTH", logarithmic),
                                 {"uSamplePositions", "uTexelSize", "uNear", "uFar", "uFootprintTan", "uTolerance"});
    if (!program) return program.error();
    t.program_ = std::move(program.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "coverage_filter");
    const GBufferLayout& layout = context.layout;
    shared.post->bindAsOutput(context);
    program_.use();
    shared.post->bindInput(layout, 0);
    glBindTextureUnit(1, layout.depthStencilTexture);
    glBindTextureUnit(2, sampleDepth_);
    program_.setVec2Array("uSamplePositions", samples_, samplePositions_.data());
    program_.set("uTexelSize", 1.0f / layout.width, 1.0f / layout.height);
    program_.set("uNear", frame.nearPlane);
    program_.set("uFar", frame.farPlane);
    program_.set("uFootprintTan", context.footprintTan(frame));
    program_.set("uTolerance", context.config.coverageTolerance);
    context.drawFullscreen();
    shared.post->copyBack(layout);
    return Status::ok();
  }

  GLuint prepassFramebuffer() const override { return prepass_.get(); }
  int samples() const override { return samples_; }
  uint64_t bytes() const override { return bytes_; }
  bool keepsObjectsFor(const Config& config) const override {
    return ownsPrepass(config) == ownPrepass_ && (!ownPrepass_ || config.samples == requestedSamples_);
  }

 private:
  ShaderProgram program_;
  GlTexture depth_;
  GlFramebuffer prepass_;
  GLuint sampleDepth_ = 0;  // the multisampled depth the filter reads
  std::vector<float> samplePositions_;
  bool ownPrepass_ = false;
  int requestedSamples_ = 0;
  int samples_ = 1;
  uint64_t bytes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Technique>> createCoverageTechnique(PluginContext& context, SharedTargets& shared) {
  return CoverageTechnique::create(context, shared);
}

}  // namespace retroaa
