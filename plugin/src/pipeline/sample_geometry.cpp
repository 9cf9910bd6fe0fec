// The multisampled depth (and normals) that the prepass methods filter with (technique.h).
#include "../technique.h"

namespace retroaa {

Result<SampleGeometry> SampleGeometry::create(PluginContext& context, SharedTargets& shared, bool ownPrepass,
                                              bool withNormals, const std::string& label) {
  SampleGeometry g;
  const GBufferLayout& layout = context.layout;
  const int normalIndex = withNormals ? findRole(layout, AttachmentRole::NormalGloss) : -1;
  g.ownsPrepass = ownPrepass;
  g.requestedSamples = context.config.samples;
  GLuint framebuffer = 0;
  if (!ownPrepass) {
    g.depth = shared.msaa->depthStencil();
    g.normal = normalIndex >= 0 ? shared.msaa->attachment(size_t(normalIndex)) : 0;
    g.samples = shared.msaa->samples();
    framebuffer = shared.msaa->framebuffer();
  } else {
    const int samples = std::max(g.requestedSamples, 1);
    g.depthTexture = makeTexture(context, GL_DEPTH24_STENCIL8, layout.width, layout.height, samples,
                                 (label + ".depth").c_str(), g.bytes);
    g.prepass = makeFramebuffer(context, (label + ".prepass").c_str());
    glNamedFramebufferTexture(g.prepass.get(), GL_DEPTH_STENCIL_ATTACHMENT, g.depthTexture.get(), 0);
    // Every location but the normal's is GL_NONE: the host's model shader writes all its outputs, the
    // prepass keeps the normal. A pair encoding (octahedral, spheremap) is whole in x and y, and so is a
    // view-space xyz normal (z ≥ 0 where the camera sees it): RG16F, 4 bytes a sample. An xyz normal in
    // any other space (world space faces away from the camera too) keeps its z, in the host's format.
    std::vector<GLenum> drawBuffers(size_t(std::max(normalIndex + 1, 1)), GL_NONE);
    if (normalIndex >= 0) {
      const bool whole = layout.normalEncoding == NormalEncoding::Xyz && !layout.normalsInViewSpace;
      g.normalTexture =
          makeTexture(context, whole ? layout.attachments[size_t(normalIndex)].internalFormat : GLenum(GL_RG16F),
                      layout.width, layout.height, samples, (label + ".normal").c_str(), g.bytes);
      glNamedFramebufferTexture(g.prepass.get(), GL_COLOR_ATTACHMENT0, g.normalTexture.get(), 0);
      drawBuffers[size_t(normalIndex)] = GL_COLOR_ATTACHMENT0;
      g.normal = g.normalTexture.get();
      g.packedNormals = layout.normalEncoding == NormalEncoding::Xyz && layout.normalsInViewSpace;
    }
    glNamedFramebufferDrawBuffers(g.prepass.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
    if (Status status = checkFramebuffer(g.prepass.get(), (label + ".prepass").c_str()); !status) return status.error();
    glGetTextureLevelParameteriv(g.depthTexture.get(), 0, GL_TEXTURE_SAMPLES, &g.samples);
    g.depth = g.depthTexture.get();
    framebuffer = g.prepass.get();
  }
  g.samplePositions.assign(size_t(g.samples) * 2, 0.5f);
  readSamplePositions(framebuffer, g.samplePositions);
  return g;
}

}  // namespace retroaa
