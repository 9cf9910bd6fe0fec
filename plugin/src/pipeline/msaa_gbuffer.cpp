#include "pipeline.h"

#include "../shared_constants.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace retroaa {

namespace {

// "W x H x N samples x B B = G GiB": the G-buffer's size, for the errors that name it.
std::string describeSize(int width, int height, int samples, uint64_t bytesPerSample) {
  char size[160];
  std::snprintf(size, sizeof size, "%d x %d x %d samples x %llu B = %.2f GiB", width, height, samples,
                static_cast<unsigned long long>(bytesPerSample),
                double(bytesPerSample) * double(width) * double(height) * double(samples) / double(1ull << 30));
  return size;
}

}  // namespace

Result<std::unique_ptr<MsaaGBuffer>> MsaaGBuffer::create(PluginContext& context, int samples, int supersample) {
  auto gbuffer = std::make_unique<MsaaGBuffer>();
  const GBufferLayout& layout = context.layout;
  // Supersampled: plain textures m× the layout's size, pixel p's sub-position s at m·p + (s mod m, s div m).
  const int scale = supersample > 1 ? supersample : 1;
  const int storageSamples = scale == 1 && samples > 1 ? samples : 0;
  const int width = layout.width * scale, height = layout.height * scale;
  const GLenum depthFormat = sizedDepthFormat(layout.depthStencilTexture);
  uint64_t bytesPerSample = bytesPerTexel(depthFormat);
  for (const Attachment& attachment : layout.attachments) bytesPerSample += bytesPerTexel(attachment.internalFormat);
  const int samplesPerTexel = std::max(storageSamples, 1);
  // What the driver's limits and the budget refuse is refused before any allocation (no GL_OUT_OF_MEMORY).
  const ContextCapabilities& caps = context.capabilities;
  if (caps.maxTextureSize > 0 && std::max(width, height) > caps.maxTextureSize)
    return Error{ErrorCode::InvalidConfig, "the " + std::string(scale > 1 ? "supersampled" : "multisampled") +
                                               " G-buffer would be " + std::to_string(width) + " x " +
                                               std::to_string(height) + ", over the context's GL_MAX_TEXTURE_SIZE " +
                                               std::to_string(caps.maxTextureSize) + ": ask for a smaller size" +
                                               (scale > 1 ? " or supersample" : "")};
  const uint64_t needed = bytesPerSample * uint64_t(width) * uint64_t(height) * uint64_t(samplesPerTexel);
  if (caps.gbufferBudgetBytes > 0 && needed > caps.gbufferBudgetBytes)
    return Error{ErrorCode::InvalidConfig,
                 "the MSAA G-buffer would take " + describeSize(width, height, samplesPerTexel, bytesPerSample) +
                     ", over its budget of " +
                     (caps.gbufferBudgetBytes >= (1u << 20) ? std::to_string(caps.gbufferBudgetBytes >> 20) + " MiB"
                                                            : std::to_string(caps.gbufferBudgetBytes >> 10) + " KiB") +
                     " (Description::gbufferBudgetBytes): ask for fewer samples, a smaller size or a larger budget"};
  gbuffer->requested_ = samples;
  gbuffer->supersample_ = scale;
  gbuffer->framebuffer_ = makeFramebuffer(context, "msaa_gbuffer");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < layout.attachments.size(); ++i) {
    const std::string label = "msaa_gbuffer." + std::to_string(i);
    gbuffer->attachments_.push_back(makeTexture(context, layout.attachments[i].internalFormat, width, height,
                                                storageSamples, label.c_str(), gbuffer->bytes_));
    glNamedFramebufferTexture(gbuffer->framebuffer(), GLenum(GL_COLOR_ATTACHMENT0 + i),
                              gbuffer->attachments_.back().get(), 0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(gbuffer->framebuffer(), GLsizei(drawBuffers.size()), drawBuffers.data());
  // The host's depth format: its model pass (depth function, reversed-Z, clear value) runs unchanged.
  gbuffer->depthStencil_ =
      makeTexture(context, depthFormat, width, height, storageSamples, "msaa_gbuffer.depth_stencil", gbuffer->bytes_);
  glNamedFramebufferTexture(gbuffer->framebuffer(),
                            hasStencil(depthFormat) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                            gbuffer->depthStencil(), 0);
  if (Status status = checkFramebuffer(gbuffer->framebuffer(), "msaa_gbuffer"); !status) {
    // A texture without storage: the driver could not allocate it (GL_OUT_OF_MEMORY). Name the size.
    GLint allocatedWidth = 0;
    glGetTextureLevelParameteriv(gbuffer->depthStencil(), 0, GL_TEXTURE_WIDTH, &allocatedWidth);
    for (size_t i = 0; allocatedWidth && i < layout.attachments.size(); ++i)
      glGetTextureLevelParameteriv(gbuffer->attachment(i), 0, GL_TEXTURE_WIDTH, &allocatedWidth);
    if (!allocatedWidth)  // within the budget, yet more than the driver has
      return Error{ErrorCode::IncompleteFramebuffer, "the driver could not allocate the MSAA G-buffer (" +
                                                         describeSize(width, height, samplesPerTexel, bytesPerSample) +
                                                         "): ask for fewer samples or a smaller size"};
    // Name what the driver refuses: each attachment alone in a framebuffer of its own.
    for (size_t i = 0; i < layout.attachments.size(); ++i) {
      GLuint probe = 0;
      glCreateFramebuffers(1, &probe);
      glNamedFramebufferTexture(probe, GL_COLOR_ATTACHMENT0, gbuffer->attachment(i), 0);
      const GLenum alone = glCheckNamedFramebufferStatus(probe, GL_FRAMEBUFFER);
      glDeleteFramebuffers(1, &probe);
      if (alone == GL_FRAMEBUFFER_COMPLETE) continue;
      char format[16];
      std::snprintf(format, sizeof format, "0x%04x", unsigned(layout.attachments[i].internalFormat));
      return Error{ErrorCode::IncompleteFramebuffer,
                   std::string("the driver cannot render into a ") + (storageSamples ? "multisampled " : "") +
                       "copy of attachment " + std::to_string(i) + " (" + roleName(layout.attachments[i].role) +
                       ", format " + format + "): give that attachment a colour-renderable format"};
    }
    return status.error();
  }
  GLint allocated = 1;
  if (storageSamples > 0) glGetTextureLevelParameteriv(gbuffer->depthStencil(), 0, GL_TEXTURE_SAMPLES, &allocated);
  gbuffer->samples_ = scale > 1 ? scale * scale : std::max(allocated, 1);
  gbuffer->multisampledStorage_ = storageSamples > 0;
  if (scale == 1 && gbuffer->samples_ != samples)
    context.warn("samples=" + std::to_string(samples) + " requested, the driver allocated " +
                 std::to_string(gbuffer->samples_) + " per pixel; resolving all " + std::to_string(gbuffer->samples_));
  return gbuffer;
}

std::vector<float> orderedGridPositions(int m) {
  std::vector<float> positions;
  for (int s = 0; s < m * m; ++s)
    positions.insert(positions.end(), {(float(s % m) + 0.5f) / float(m), (float(s / m) + 0.5f) / float(m)});
  return positions;
}

std::vector<float> MsaaGBuffer::samplePositions() const {
  if (supersample_ > 1) return orderedGridPositions(supersample_);
  std::vector<float> positions(size_t(samples_) * 2, 0.5f);
  if (multisampled()) readSamplePositions(framebuffer(), positions);
  return positions;
}

int findRole(const GBufferLayout& layout, AttachmentRole role) {
  for (size_t i = 0; i < layout.attachments.size(); ++i)
    if (layout.attachments[i].role == role) return static_cast<int>(i);
  return -1;
}

namespace {
// FSO's shaders get GLOBAL_FAR_Z as a #define; ours too, printed so that it reads back exactly.
std::string fsoFarDefine(const DepthEncoding& encoding) {
  if (encoding.kind != DepthEncoding::Kind::FsoCompressedViewZ) return "";
  char text[64];
  std::snprintf(text, sizeof text, "#define FSO_GLOBAL_FAR_Z %.9e\n", double(encoding.farDistance));
  return text;
}
}  // namespace

std::string depthEncodingDefines(const GBufferLayout& layout) {
  return defineLine("DEPTH_SOURCE", int(layout.depthSource)) + defineLine("DEPTH_CHANNEL", layout.depthChannel) +
         defineLine("DEPTH_ENCODING", int(layout.depthEncoding.kind)) + fsoFarDefine(layout.depthEncoding) +
         defineLine("DEPTH_BUFFER_ENCODING", int(layout.depthBufferEncoding)) +
         defineLine("NORMAL_ENCODING", int(layout.normalEncoding));
}

std::string MsaaGBuffer::shaderDefines(const GBufferLayout& layout, bool withOutputs) const {
  const size_t count = layout.attachments.size();
  std::string d = defineLine("SAMPLES", samples_) + defineLine("MULTISAMPLED", multisampled()) +
                  defineLine("SUPERSAMPLE", supersample_) + defineLine("ATTACHMENT_COUNT", int(count)) +
                  defineLine("POSITION_ATTACHMENT", findRole(layout, AttachmentRole::ViewPosition)) +
                  defineLine("NORMAL_ATTACHMENT", findRole(layout, AttachmentRole::NormalGloss)) +
                  defineLine("ALBEDO_ATTACHMENT", findRole(layout, AttachmentRole::Albedo)) +
                  defineLine("SPECULAR_ATTACHMENT", findRole(layout, AttachmentRole::Specular)) +
                  defineLine("EMISSIVE_ATTACHMENT", findRole(layout, AttachmentRole::Emissive)) +
                  depthEncodingDefines(layout);
  // M(0) M(1) ... for each attachment: a loop over the attachments that accumulates into an array of
  // them (or indexes uAttachments) may not unroll, and llvmpipe then keeps the array in scratch memory;
  // aggregate's slice write took 5-6x its floor in SuperTuxKart that way, 2x with constant indices.
  // One statement (braced), so that it can be a loop's whole body.
  std::string forEach = "#define FOR_EACH_ATTACHMENT(M) {";
  for (size_t i = 0; i < count; ++i) forEach += " M(" + std::to_string(i) + ")";
  d += forEach + " }\n";
  std::string store = "#define STORE_OUTPUTS(v)";
  for (size_t i = 0; i < count && withOutputs; ++i) {
    d += "layout(location = " + std::to_string(i) + ") out vec4 out" + std::to_string(i) + ";\n";
    store += " out" + std::to_string(i) + " = v[" + std::to_string(i) + "];";
  }
  return d + store + "\n";
}

void MsaaGBuffer::bind(const GBufferLayout& layout) const {
  for (size_t i = 0; i < layout.attachments.size(); ++i) glBindTextureUnit(GLuint(i), attachment(i));
  glBindTextureUnit(kUnitDepthStencil, depthStencil());
}

void MsaaGBuffer::beginPass(const ShaderProgram& program, const PluginContext& context, const FrameInfo& frame) const {
  program.use();
  bind(context.layout);
  program.setDepthEncoding(context);
  program.set("uFootprintTan", context.footprintTan(frame));
}

}  // namespace retroaa
