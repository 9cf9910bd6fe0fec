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

class ReconstructTechnique : public SampleGeometryTechnique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<ReconstructTechnique>();
    if (Status status = technique->createGeometry(context, shared, Method::Reconstruct, true, "reconstruct"); !status)
      return status.error();
    ReconstructTechnique& t = *technique;
    const GBufferLayout& layout = context.layout;
    for (const Attachment& a : layout.attachments)
      if (a.role == AttachmentRole::NormalGloss) t.pixelNormal_ = a.texture;
    const bool logarithmic = layout.depthBufferEncoding == DepthBufferEncoding::Logarithmic;
    auto program = context.shaders->program("common/fullscreen.vert", "reconstruct/reconstruct.frag",
                                            defineLine("SAMPLES", t.geometry_.samples) +
                                                defineLine("LOGARITHMIC_DEPTH", logarithmic) +
                                                defineLine("HAS_NORMALS", t.geometry_.normal != 0) +
                                                defineLine("PACKED_SAMPLE_NORMALS", t.geometry_.packedNormals),
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
    glBindTextureUnit(3, geometry_.depth);
    glBindTextureUnit(4, geometry_.normal);
    program_.setVec2Array("uSamplePositions", geometry_.samples, geometry_.samplePositions.data());
    program_.set("uNear", frame.nearPlane);
    program_.set("uFar", frame.farPlane);
    program_.set("uFootprintTan", context.footprintTan(frame));
    program_.set("uTolerance", context.config.reconstructTolerance);
    context.drawFullscreen();
    shared.post->copyBack(layout);
    return Status::ok();
  }

 private:
  ShaderProgram program_;
  GLuint pixelNormal_ = 0;  // the host's single-sample normal attachment (0: the layout has none)
};

}  // namespace

Result<std::unique_ptr<Technique>> createReconstructTechnique(PluginContext& context, SharedTargets& shared) {
  return ReconstructTechnique::create(context, shared);
}

}  // namespace retroaa
