#include "methods.h"

#include <algorithm>
#include <string>

namespace retroaa {

Result<std::unique_ptr<MsaaGBuffer>> MsaaGBuffer::create(PluginContext& context, int samples) {
  auto gbuffer = std::make_unique<MsaaGBuffer>();
  const GBufferLayout& layout = context.layout;
  const int storageSamples = samples > 1 ? samples : 0;
  gbuffer->requested_ = samples;
  gbuffer->framebuffer_ = makeFramebuffer(context, "msaa_gbuffer");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < layout.attachments.size(); ++i) {
    const std::string label = "msaa_gbuffer." + std::to_string(i);
    gbuffer->attachments_.push_back(makeTexture(context, layout.attachments[i].internalFormat, layout.width,
                                                layout.height, storageSamples, label.c_str(), gbuffer->bytes_));
    glNamedFramebufferTexture(gbuffer->framebuffer(), GLenum(GL_COLOR_ATTACHMENT0 + i),
                              gbuffer->attachments_.back().get(), 0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(gbuffer->framebuffer(), GLsizei(drawBuffers.size()), drawBuffers.data());
  gbuffer->depthStencil_ = makeTexture(context, GL_DEPTH24_STENCIL8, layout.width, layout.height, storageSamples,
                                       "msaa_gbuffer.depth_stencil", gbuffer->bytes_);
  glNamedFramebufferTexture(gbuffer->framebuffer(), GL_DEPTH_STENCIL_ATTACHMENT, gbuffer->depthStencil(), 0);
  if (Status status = checkFramebuffer(gbuffer->framebuffer(), "msaa_gbuffer"); !status) return status.error();
  GLint allocated = 1;
  if (storageSamples > 0) glGetTextureLevelParameteriv(gbuffer->depthStencil(), 0, GL_TEXTURE_SAMPLES, &allocated);
  gbuffer->samples_ = std::max(allocated, 1);
  gbuffer->multisampledStorage_ = storageSamples > 0;
  if (gbuffer->samples_ != samples)
    context.warn("samples=" + std::to_string(samples) + " requested, the driver allocated " +
                 std::to_string(gbuffer->samples_) + " per pixel; resolving all " + std::to_string(gbuffer->samples_));
  return gbuffer;
}

namespace {
int findRole(const GBufferLayout& layout, AttachmentRole role) {
  for (size_t i = 0; i < layout.attachments.size(); ++i)
    if (layout.attachments[i].role == role) return static_cast<int>(i);
  return -1;
}
}  // namespace

std::string MsaaGBuffer::shaderDefines(const GBufferLayout& layout, bool withOutputs) const {
  const size_t count = layout.attachments.size();
  std::string d;
  d += "#define SAMPLES " + std::to_string(samples_) + "\n";
  d += "#define MULTISAMPLED " + std::string(multisampled() ? "1" : "0") + "\n";
  d += "#define ATTACHMENT_COUNT " + std::to_string(count) + "\n";
  d += "#define POSITION_ATTACHMENT " + std::to_string(findRole(layout, AttachmentRole::ViewPosition)) + "\n";
  d += "#define NORMAL_ATTACHMENT " + std::to_string(findRole(layout, AttachmentRole::NormalGloss)) + "\n";
  d += "#define ALBEDO_ATTACHMENT " + std::to_string(findRole(layout, AttachmentRole::Albedo)) + "\n";
  d += "#define SPECULAR_ATTACHMENT " + std::to_string(findRole(layout, AttachmentRole::Specular)) + "\n";
  d += "#define DEPTH_CHANNEL " + std::to_string(layout.depthChannel) + "\n";
  d += "#define DEPTH_ENCODING " +
       std::string(layout.depthEncoding.kind == DepthEncoding::Kind::LogAboveKnee ? "1" : "0") + "\n";
  std::string store = "#define STORE_OUTPUTS(v)";
  for (size_t i = 0; i < count && withOutputs; ++i) {
    d += "layout(location = " + std::to_string(i) + ") out vec4 out" + std::to_string(i) + ";\n";
    store += " out" + std::to_string(i) + " = v[" + std::to_string(i) + "];";
  }
  return d + store + "\n";
}

void MsaaGBuffer::bind(const GBufferLayout& layout) const {
  for (size_t i = 0; i < layout.attachments.size(); ++i) glBindTextureUnit(GLuint(i), attachment(i));
  glBindTextureUnit(15, depthStencil());
}

void setDepthEncodingUniforms(GLuint program, const GBufferLayout& layout) {
  glUniform1f(glGetUniformLocation(program, "uDepthKnee"), layout.depthEncoding.knee);
  glUniform1f(glGetUniformLocation(program, "uBackgroundAbove"), layout.depthEncoding.backgroundAbove);
}

}  // namespace retroaa
