// `reconstruct` (after Chajdas, McGuire and Luebke, "Subpixel Reconstruction Antialiasing", I3D 2011):
// shading stays the host's stock single-sample path; a multisampled prepass of the host's own model
// shaders keeps only depth and the normal; after tonemapping, every sub-sample that does not belong to
// its own pixel's surface takes the colour of the neighbouring shaded pixels that match it
// (shaders/reconstruct/). Stacked on a G-buffer method (`reconstruct_filter=on`) it reads the MSAA
// G-buffer's own depth and normals instead of a prepass.
#include <string>

#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

bool ownsPrepass(const Config& config) { return config.method == Method::Reconstruct; }

int normalAttachment(const GBufferLayout& layout) {
  for (size_t i = 0; i < layout.attachments.size(); ++i)
    if (layout.attachments[i].role == AttachmentRole::NormalGloss) return int(i);
  return -1;
}

class ReconstructTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<ReconstructTechnique>();
    ReconstructTechnique& t = *technique;
    const GBufferLayout& layout = context.layout;
    const int normalIndex = normalAttachment(layout);
    t.ownPrepass_ = ownsPrepass(context.config);
    t.requestedSamples_ = context.config.samples;
    GLuint framebuffer = 0;
    bool packedNormal = false;
    if (!t.ownPrepass_) {
      t.sampleDepth_ = shared.msaa->depthStencil();
      t.sampleNormal_ = normalIndex >= 0 ? shared.msaa->attachment(size_t(normalIndex)) : 0;
      t.samples_ = shared.msaa->samples();
      framebuffer = shared.msaa->framebuffer();
    } else {
      const int samples = std::max(t.requestedSamples_, 1);
      t.depth_ = makeTexture(context, GL_DEPTH24_STENCIL8, layout.width, layout.height, samples, "reconstruct.depth",
                             t.bytes_);
      t.prepass_ = makeFramebuffer(context, "reconstruct.prepass");
      glNamedFramebufferTexture(t.prepass_.get(), GL_DEPTH_STENCIL_ATTACHMENT, t.depth_.get(), 0);
      // Only the normal output of the host's model shader is kept, in RG16F: x and y of the unit view-space
      // normal (z ≥ 0 for what the camera sees), 4 bytes a sample instead of the G-buffer's 8.
      std::vector<GLenum> drawBuffers(size_t(std::max(normalIndex + 1, 1)), GL_NONE);
      if (normalIndex >= 0) {
        t.normal_ =
            makeTexture(context, GL_RG16F, layout.width, layout.height, samples, "reconstruct.normal", t.bytes_);
        glNamedFramebufferTexture(t.prepass_.get(), GL_COLOR_ATTACHMENT0, t.normal_.get(), 0);
        drawBuffers[size_t(normalIndex)] = GL_COLOR_ATTACHMENT0;
        t.sampleNormal_ = t.normal_.get();
        packedNormal = true;
      }
      glNamedFramebufferDrawBuffers(t.prepass_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
      if (Status status = checkFramebuffer(t.prepass_.get(), "reconstruct.prepass"); !status) return status.error();
      glGetTextureLevelParameteriv(t.depth_.get(), 0, GL_TEXTURE_SAMPLES, &t.samples_);
      t.sampleDepth_ = t.depth_.get();
      framebuffer = t.prepass_.get();
    }
    t.pixelNormal_ = normalIndex >= 0 ? layout.attachments[size_t(normalIndex)].texture : 0;
    t.samplePositions_.assign(size_t(t.samples_) * 2, 0.5f);
    readSamplePositions(framebuffer, t.samplePositions_);
    const bool logarithmic = layout.depthBufferEncoding == DepthBufferEncoding::Logarithmic;
    auto program = context.shaders->program(
        "common/fullscreen.vert", "reconstruct/reconstruct.frag",
        defineLine("SAMPLES", t.samples_) + defineLine("LOGARITHMIC_DEPTH", logarithmic) +
            defineLine("HAS_NORMALS", normalIndex >= 0) + defineLine("PACKED_SAMPLE_NORMALS", packedNormal),
        {"uSamplePositions", "uNear", "uFar", "uFootprintTan", "uTolerance"});
    if (!program) return program.error();
    t.program_ = std::move(program.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "reconstruct");
    const GBufferLayout& layout = context.layout;
    shared.post->bindAsOutput(context);
    program_.use();
    shared.post->bindInput(layout, 0);
    glBindTextureUnit(1, layout.depthStencilTexture);
    glBindTextureUnit(2, pixelNormal_);
    glBindTextureUnit(3, sampleDepth_);
    glBindTextureUnit(4, sampleNormal_);
    program_.setVec2Array("uSamplePositions", samples_, samplePositions_.data());
    program_.set("uNear", frame.nearPlane);
    program_.set("uFar", frame.farPlane);
    program_.set("uFootprintTan", context.footprintTan(frame));
    program_.set("uTolerance", context.config.reconstructTolerance);
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
  GlTexture depth_, normal_;
  GlFramebuffer prepass_;
  GLuint sampleDepth_ = 0, sampleNormal_ = 0;  // what the pass reads: its prepass or the MSAA G-buffer
  GLuint pixelNormal_ = 0;                     // the host's single-sample normal attachment
  std::vector<float> samplePositions_;
  bool ownPrepass_ = false;
  int requestedSamples_ = 0;
  int samples_ = 1;
  uint64_t bytes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Technique>> createReconstructTechnique(PluginContext& context, SharedTargets& shared) {
  return ReconstructTechnique::create(context, shared);
}

}  // namespace retroaa
