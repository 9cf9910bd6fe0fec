#include "context.h"

#include "gl_basics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace retroaa {

void PluginContext::warn(const std::string& message) {
  warnings.push_back(message);
  if (log) log(LogLevel::Warning, message);
}

void PluginContext::inform(const std::string& message) {
  if (log) log(LogLevel::Info, message);
}

float PluginContext::footprintTan(const FrameInfo& frame) const {
  const float aspect = float(layout.width) / float(layout.height);
  const float horizontalFov = 2.0f * std::atan(std::tan(frame.verticalFovRadians * 0.5f) * aspect);
  return std::tan(horizontalFov / float(layout.width));
}

void PluginContext::drawFullscreen() const {
  if (floors) floors->recordDraw();
  glBindVertexArray(wholeScreenVertexArray.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void PluginContext::drawTiles(const TileDraw& tiles) const {
  if (!tiles.vertexArray) return drawFullscreen();
  if (floors) floors->recordDraw(tiles);
  glBindVertexArray(tiles.vertexArray);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, tiles.commands);
  glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(tiles.offset));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);  // the host's lighting callback finds none of ours bound
}

void PluginContext::beginFullscreenPass(GLuint framebuffer) const {
  if (framebuffer) glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, layout.width, layout.height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void PluginContext::dispatchOverScreen(const std::vector<ImageOutput>& outputs, int tileSize) const {
  dispatchOver(outputs, layout.width, layout.height, tileSize);
}

void PluginContext::dispatchOver(const std::vector<ImageOutput>& outputs, int width, int height, int tileSize) const {
  if (floors) floors->recordDispatch(outputs, width, height, tileSize);
  for (size_t unit = 0; unit < outputs.size(); ++unit)
    glBindImageTexture(GLuint(unit), outputs[unit].texture, 0, GL_FALSE, 0, GL_WRITE_ONLY, outputs[unit].format);
  glDispatchCompute(GLuint((width + tileSize - 1) / tileSize), GLuint((height + tileSize - 1) / tileSize), 1);
  // Whatever reads the output next (a texture fetch, a blend, a copy, the host's readback) sees the stores.
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  for (size_t unit = 0; unit < outputs.size(); ++unit)
    glBindImageTexture(GLuint(unit), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, outputs[unit].format);
}

void PluginContext::beginDepthWritingPass(GLuint framebuffer) const {
  beginFullscreenPass(framebuffer);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
}

ScopedPass::ScopedPass(PluginContext& context, const char* name, uint64_t minimumBytes) : context_(context) {
  const std::string label = std::string("retroaa.") + name;
  glPushDebugGroup(GL_DEBUG_SOURCE_THIRD_PARTY, 0, -1, label.c_str());
  context_.statistics->beginPass(name, context_.timePasses, minimumBytes);
  if (context_.floors) context_.floors->open(name);
}

ScopedPass::~ScopedPass() {
  context_.statistics->endPass();
  if (context_.floors) context_.floors->close(*context_.statistics, context_.wholeScreenVertexArray.get());
  glPopDebugGroup();
}

Status checkFramebuffer(GLuint framebuffer, const char* label) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return Status::ok();
  std::ostringstream message;
  message << "framebuffer '" << label << "' is incomplete (status 0x" << std::hex << status << ")";
  return Error{ErrorCode::IncompleteFramebuffer, message.str()};
}

GlTexture makeLightTargetCopy(PluginContext& context, const char* label, uint64_t& bytes) {
  const GBufferLayout& layout = context.layout;
  GLint format = GL_RGBA16F;
  glGetTextureLevelParameteriv(sceneColourTexture(layout), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return makeTexture(context, GLenum(format), layout.width, layout.height, 0, label, bytes);
}

void copyLightTarget(const GBufferLayout& layout, GLuint copy) {
  copyLayoutTexture(layout, sceneColourTexture(layout), copy);
}

void copyLayoutTexture(const GBufferLayout& layout, GLuint from, GLuint to) {
  glCopyImageSubData(from, GL_TEXTURE_2D, 0, 0, 0, 0, to, GL_TEXTURE_2D, 0, 0, 0, 0, layout.width, layout.height, 1);
}

bool holdsFloats(GLuint texture) {
  GLint redType = 0;
  if (texture && glIsTexture(texture)) glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_RED_TYPE, &redType);
  return redType == GL_FLOAT;
}

uint64_t bytesPerTexel(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_RGBA32F: return 16;
    case GL_RGBA16F: return 8;
    case GL_RG32UI: return 8;
    case GL_R16F: return 2;
    case GL_R8UI: return 1;
    case GL_RG16F: return 4;
    case GL_R32F: return 4;
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_RGB10_A2:
    case GL_R11F_G11F_B10F:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH_COMPONENT32F: return 4;
    case GL_DEPTH32F_STENCIL8: return 8;
    case GL_DEPTH_COMPONENT24: return 4;
    case GL_DEPTH_COMPONENT16: return 2;
    case GL_R8:
    case GL_STENCIL_INDEX8: return 1;
    case GL_RG8: return 2;
    default: return 16;  // unknown formats: count generously rather than hide memory
  }
}

bool takesImageStores(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_RGBA32F:
    case GL_RGBA16F:
    case GL_RG32F:
    case GL_RG16F:
    case GL_R11F_G11F_B10F:
    case GL_R32F:
    case GL_R16F:
    case GL_RGBA16:
    case GL_RGB10_A2:
    case GL_RGBA8:
    case GL_RG16:
    case GL_RG8:
    case GL_R16:
    case GL_R8:
    case GL_RGBA16_SNORM:
    case GL_RGBA8_SNORM:
    case GL_RG16_SNORM:
    case GL_RG8_SNORM:
    case GL_R16_SNORM:
    case GL_R8_SNORM: return true;
    default: return false;
  }
}

GLenum sizedDepthFormat(GLuint texture) {
  if (!texture || !glIsTexture(texture)) return 0;
  GLint format = 0, depthBits = 0, stencilBits = 0, depthType = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  switch (format) {
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT16: return GLenum(format);
    default: break;
  }
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH_SIZE, &depthBits);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_STENCIL_SIZE, &stencilBits);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH_TYPE, &depthType);
  if (depthBits == 0) return 0;
  const bool floating = depthType == GL_FLOAT;
  if (stencilBits > 0) return floating ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
  if (floating) return GL_DEPTH_COMPONENT32F;
  return depthBits > 16 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT16;
}

const char* roleName(AttachmentRole role) {
  switch (role) {
    case AttachmentRole::Albedo: return "Albedo";
    case AttachmentRole::ViewPosition: return "ViewPosition";
    case AttachmentRole::NormalGloss: return "NormalGloss";
    case AttachmentRole::Specular: return "Specular";
    case AttachmentRole::Emissive: return "Emissive";
    case AttachmentRole::Other: return "Other";
  }
  return "?";
}

namespace {
bool isUnsizedColour(GLenum format) {
  return format == GL_RGBA || format == GL_RGB || format == GL_RG || format == GL_RED;
}
}  // namespace

GLenum sizedColourFormat(GLuint texture, GLenum declared) {
  if (!isUnsizedColour(declared)) return declared;
  if (!texture || !glIsTexture(texture)) return 0;
  GLint format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  if (!isUnsizedColour(GLenum(format))) return GLenum(format);  // the driver reports the sized one
  GLint sizes[4] = {}, type = 0;
  const GLenum sizeQueries[4] = {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                 GL_TEXTURE_ALPHA_SIZE};
  for (int c = 0; c < 4; ++c) glGetTextureLevelParameteriv(texture, 0, sizeQueries[c], &sizes[c]);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_RED_TYPE, &type);
  const int channels = sizes[3] ? 4 : sizes[2] ? 3 : sizes[1] ? 2 : sizes[0] ? 1 : 0;
  struct Row {
    int channels, bits;
    GLint type;
    GLenum format;
  };
  static const Row rows[] = {
      {4, 8, GL_UNSIGNED_NORMALIZED, GL_RGBA8},
      {3, 8, GL_UNSIGNED_NORMALIZED, GL_RGB8},
      {2, 8, GL_UNSIGNED_NORMALIZED, GL_RG8},
      {1, 8, GL_UNSIGNED_NORMALIZED, GL_R8},
      {4, 16, GL_UNSIGNED_NORMALIZED, GL_RGBA16},
      {4, 16, GL_FLOAT, GL_RGBA16F},
      {3, 16, GL_FLOAT, GL_RGB16F},
      {2, 16, GL_FLOAT, GL_RG16F},
      {1, 16, GL_FLOAT, GL_R16F},
      {4, 32, GL_FLOAT, GL_RGBA32F},
      {3, 32, GL_FLOAT, GL_RGB32F},
      {2, 32, GL_FLOAT, GL_RG32F},
      {1, 32, GL_FLOAT, GL_R32F},
  };
  for (const Row& row : rows)
    if (row.channels == channels && row.bits == sizes[0] && row.type == type) return row.format;
  return 0;
}

GLenum sizedDepthRenderbufferFormat(GLuint renderbuffer) {
  GLint format = 0, depthBits = 0, stencilBits = 0;
  glGetNamedRenderbufferParameteriv(renderbuffer, GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
  if (format != GL_DEPTH_COMPONENT && format != GL_DEPTH_STENCIL) return GLenum(format);
  glGetNamedRenderbufferParameteriv(renderbuffer, GL_RENDERBUFFER_DEPTH_SIZE, &depthBits);
  glGetNamedRenderbufferParameteriv(renderbuffer, GL_RENDERBUFFER_STENCIL_SIZE, &stencilBits);
  // A renderbuffer reports no depth type: 32 bits is taken as float (the only 32-bit depth-stencil format).
  if (stencilBits > 0) return depthBits > 24 ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
  return depthBits > 24 ? GL_DEPTH_COMPONENT32F : depthBits > 16 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT16;
}

bool hasStencil(GLenum depthFormat) {
  return depthFormat == GL_DEPTH24_STENCIL8 || depthFormat == GL_DEPTH32F_STENCIL8;
}

GlTexture makeTexture(PluginContext& context, GLenum internalFormat, int width, int height, int samples,
                      const char* label, uint64_t& bytes) {
  GLuint name = 0;
  if (samples > 0) {
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &name);
    glTextureStorage2DMultisample(name, samples, internalFormat, width, height, GL_TRUE);
  } else {
    name = gl_basics::createTexelTexture2D(internalFormat, width, height);
  }
  const std::string fullLabel = std::string("retroaa.") + label;
  glObjectLabel(GL_TEXTURE, name, -1, fullLabel.c_str());
  // Count what the driver allocated: llvmpipe, for one, backs 1x and 2x requests with 4 samples.
  GLint allocated = 1;
  if (samples > 0) glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_SAMPLES, &allocated);
  bytes += bytesPerTexel(internalFormat) * uint64_t(width) * uint64_t(height) * uint64_t(std::max(allocated, 1));
  return GlTexture(context.objects, name);
}

void readSamplePositions(GLuint framebuffer, std::vector<float>& positionsXY) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  for (GLint s = 0; s < samples && 2 * size_t(s) + 1 < positionsXY.size(); ++s)
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(s), &positionsXY[2 * s]);
}

GlFramebuffer makeFramebuffer(PluginContext& context, const char* label) {
  GLuint name = 0;
  glCreateFramebuffers(1, &name);
  const std::string fullLabel = std::string("retroaa.") + label;
  glObjectLabel(GL_FRAMEBUFFER, name, -1, fullLabel.c_str());
  return GlFramebuffer(context.objects, name);
}

GlBuffer makeBuffer(PluginContext& context, GLsizeiptr bytes, const void* data, const char* label, uint64_t& total) {
  GLuint name = 0;
  glCreateBuffers(1, &name);
  glNamedBufferStorage(name, bytes, data, GL_DYNAMIC_STORAGE_BIT);
  const std::string fullLabel = std::string("retroaa.") + label;
  glObjectLabel(GL_BUFFER, name, -1, fullLabel.c_str());
  total += uint64_t(bytes);
  return GlBuffer(context.objects, name);
}

GlVertexArray makeRectangleArray(PluginContext& context, GLuint rectangles, const char* label) {
  GLuint name = 0;
  glCreateVertexArrays(1, &name);
  glEnableVertexArrayAttrib(name, 0);
  glVertexArrayAttribFormat(name, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(name, 0, 0);
  glVertexArrayVertexBuffer(name, 0, rectangles, 0, 4 * sizeof(float));
  glVertexArrayBindingDivisor(name, 0, 1);
  const std::string fullLabel = std::string("retroaa.") + label;
  glObjectLabel(GL_VERTEX_ARRAY, name, -1, fullLabel.c_str());
  return GlVertexArray(context.objects, name);
}

}  // namespace retroaa
