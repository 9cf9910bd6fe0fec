#include "gl_state.h"

#include <algorithm>
#include <iterator>

namespace retroaa {

namespace {
GLint getInt(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}
void setEnabled(GLenum capability, GLboolean enabled) {
  if (enabled)
    glEnable(capability);
  else
    glDisable(capability);
}
// The generic binding query and the indexed ones of an indexed buffer target, and how many indices it has.
struct BufferQueries {
  GLenum generic, buffer, start, size, count;
};
BufferQueries queriesOf(GLenum target) {
  switch (target) {
    case GL_ATOMIC_COUNTER_BUFFER:
      return {GL_ATOMIC_COUNTER_BUFFER_BINDING, GL_ATOMIC_COUNTER_BUFFER_BINDING, GL_ATOMIC_COUNTER_BUFFER_START,
              GL_ATOMIC_COUNTER_BUFFER_SIZE, GL_MAX_ATOMIC_COUNTER_BUFFER_BINDINGS};
    case GL_SHADER_STORAGE_BUFFER:
      return {GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
              GL_SHADER_STORAGE_BUFFER_SIZE, GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS};
    default:
      return {GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE,
              GL_MAX_UNIFORM_BUFFER_BINDINGS};
  }
}

GlStateSnapshot::IndexedBuffers captureBuffers(GLenum target) {
  const BufferQueries q = queriesOf(target);
  GlStateSnapshot::IndexedBuffers buffers;
  buffers.generic = getInt(q.generic);
  buffers.ranges.resize(size_t(std::min(GlStateSnapshot::kBufferIndices, getInt(q.count))));
  for (GLuint index = 0; index < buffers.ranges.size(); ++index) {
    GlStateSnapshot::BufferRange& range = buffers.ranges[index];
    glGetIntegeri_v(q.buffer, index, &range.buffer);
    glGetInteger64i_v(q.start, index, &range.start);
    glGetInteger64i_v(q.size, index, &range.size);
  }
  return buffers;
}

GLenum bindingQueryOf(GLenum target) {
  switch (target) {
    case GL_PIXEL_PACK_BUFFER: return GL_PIXEL_PACK_BUFFER_BINDING;
    case GL_PIXEL_UNPACK_BUFFER: return GL_PIXEL_UNPACK_BUFFER_BINDING;
    case GL_QUERY_BUFFER: return GL_QUERY_BUFFER_BINDING;
    case GL_DRAW_INDIRECT_BUFFER: return GL_DRAW_INDIRECT_BUFFER_BINDING;
    case GL_DISPATCH_INDIRECT_BUFFER: return GL_DISPATCH_INDIRECT_BUFFER_BINDING;
    case GL_COPY_READ_BUFFER: return GL_COPY_READ_BUFFER_BINDING;
    case GL_COPY_WRITE_BUFFER: return GL_COPY_WRITE_BUFFER_BINDING;
    case GL_ARRAY_BUFFER: return GL_ARRAY_BUFFER_BINDING;
    default: return GL_TEXTURE_BUFFER_BINDING;
  }
}

// A name the host deleted while it was bound is gone once unbound: it restores to 0.
GLuint liveBuffer(GLint name) { return name != 0 && glIsBuffer(GLuint(name)) ? GLuint(name) : 0; }

void restoreBuffers(GLenum target, const GlStateSnapshot::IndexedBuffers& buffers) {
  for (GLuint index = 0; index < buffers.ranges.size(); ++index) {  // each also sets the generic binding
    const GlStateSnapshot::BufferRange& range = buffers.ranges[index];
    const GLuint buffer = liveBuffer(range.buffer);
    if (buffer && range.size > 0)
      glBindBufferRange(target, index, buffer, GLintptr(range.start), GLsizeiptr(range.size));
    else
      glBindBufferBase(target, index, buffer);
  }
  glBindBuffer(target, liveBuffer(buffers.generic));
}
}  // namespace

GlStateSnapshot GlStateSnapshot::capture() {
  GlStateSnapshot s;
  s.drawFramebuffer = getInt(GL_DRAW_FRAMEBUFFER_BINDING);
  s.readFramebuffer = getInt(GL_READ_FRAMEBUFFER_BINDING);
  s.program = getInt(GL_CURRENT_PROGRAM);
  s.vertexArray = getInt(GL_VERTEX_ARRAY_BINDING);
  s.activeTexture = getInt(GL_ACTIVE_TEXTURE);
  glGetIntegerv(GL_VIEWPORT, s.viewport.data());
  glGetIntegerv(GL_SCISSOR_BOX, s.scissorBox.data());
  s.blend = glIsEnabled(GL_BLEND);
  s.depthTest = glIsEnabled(GL_DEPTH_TEST);
  s.stencilTest = glIsEnabled(GL_STENCIL_TEST);
  s.cullFace = glIsEnabled(GL_CULL_FACE);
  s.scissorTest = glIsEnabled(GL_SCISSOR_TEST);
  s.multisample = glIsEnabled(GL_MULTISAMPLE);
  s.sampleShading = glIsEnabled(GL_SAMPLE_SHADING);
  s.framebufferSrgb = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &s.depthMask);
  glGetBooleanv(GL_COLOR_WRITEMASK, s.colorMask.data());
  s.blendSrcRgb = getInt(GL_BLEND_SRC_RGB);
  s.blendDstRgb = getInt(GL_BLEND_DST_RGB);
  s.blendSrcAlpha = getInt(GL_BLEND_SRC_ALPHA);
  s.blendDstAlpha = getInt(GL_BLEND_DST_ALPHA);
  s.blendEquationRgb = getInt(GL_BLEND_EQUATION_RGB);
  s.blendEquationAlpha = getInt(GL_BLEND_EQUATION_ALPHA);
  s.depthFunc = getInt(GL_DEPTH_FUNC);
  s.cullFaceMode = getInt(GL_CULL_FACE_MODE);
  s.stencilFunc = getInt(GL_STENCIL_FUNC);
  s.stencilRef = getInt(GL_STENCIL_REF);
  s.stencilValueMask = getInt(GL_STENCIL_VALUE_MASK);
  s.stencilWriteMask = getInt(GL_STENCIL_WRITEMASK);
  s.stencilFail = getInt(GL_STENCIL_FAIL);
  s.stencilPassDepthFail = getInt(GL_STENCIL_PASS_DEPTH_FAIL);
  s.stencilPassDepthPass = getInt(GL_STENCIL_PASS_DEPTH_PASS);
  s.backStencilFunc = getInt(GL_STENCIL_BACK_FUNC);
  s.backStencilRef = getInt(GL_STENCIL_BACK_REF);
  s.backStencilValueMask = getInt(GL_STENCIL_BACK_VALUE_MASK);
  s.backStencilWriteMask = getInt(GL_STENCIL_BACK_WRITEMASK);
  s.backStencilFail = getInt(GL_STENCIL_BACK_FAIL);
  s.backStencilPassDepthFail = getInt(GL_STENCIL_BACK_PASS_DEPTH_FAIL);
  s.backStencilPassDepthPass = getInt(GL_STENCIL_BACK_PASS_DEPTH_PASS);
  glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &s.minSampleShading);
  s.textureBindings2D.resize(kUnits);
  s.textureBindings2DMultisample.resize(kUnits);
  s.samplerBindings.resize(kUnits);
  for (int unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    s.textureBindings2D[unit] = getInt(GL_TEXTURE_BINDING_2D);
    s.textureBindings2DMultisample[unit] = getInt(GL_TEXTURE_BINDING_2D_MULTISAMPLE);
    s.samplerBindings[unit] = getInt(GL_SAMPLER_BINDING);
  }
  glActiveTexture(s.activeTexture);
  s.imageBindings.resize(size_t(std::min(kImageUnits, getInt(GL_MAX_IMAGE_UNITS))));
  for (GLuint unit = 0; unit < s.imageBindings.size(); ++unit) {
    ImageBinding& image = s.imageBindings[unit];
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, unit, &image.texture);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, unit, &image.level);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, unit, &image.layered);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, unit, &image.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, unit, &image.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, unit, &image.format);
  }
  s.packAlignment = getInt(GL_PACK_ALIGNMENT);
  s.unpackAlignment = getInt(GL_UNPACK_ALIGNMENT);
  s.packRowLength = getInt(GL_PACK_ROW_LENGTH);
  s.packSkipPixels = getInt(GL_PACK_SKIP_PIXELS);
  s.packSkipRows = getInt(GL_PACK_SKIP_ROWS);
  s.atomicCounterBuffers = captureBuffers(GL_ATOMIC_COUNTER_BUFFER);
  s.shaderStorageBuffers = captureBuffers(GL_SHADER_STORAGE_BUFFER);
  s.uniformBuffers = captureBuffers(GL_UNIFORM_BUFFER);
  for (size_t i = 0; i < std::size(kPlainBufferTargets); ++i) s.plainBuffers[i] = getInt(bindingQueryOf(kPlainBufferTargets[i]));
  s.drawBuffers.resize(size_t(std::min(kDrawBuffers, getInt(GL_MAX_DRAW_BUFFERS))));
  for (GLuint i = 0; i < s.drawBuffers.size(); ++i) {
    DrawBufferState& d = s.drawBuffers[i];
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, d.colorMask.data());
    d.blend = glIsEnabledi(GL_BLEND, i);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, i, &d.srcRgb);
    glGetIntegeri_v(GL_BLEND_DST_RGB, i, &d.dstRgb);
    glGetIntegeri_v(GL_BLEND_SRC_ALPHA, i, &d.srcAlpha);
    glGetIntegeri_v(GL_BLEND_DST_ALPHA, i, &d.dstAlpha);
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, i, &d.equationRgb);
    glGetIntegeri_v(GL_BLEND_EQUATION_ALPHA, i, &d.equationAlpha);
  }
  return s;
}

GlStateGuard::GlStateGuard() : saved_(GlStateSnapshot::capture()) {
  glBindSamplers(0, GlStateSnapshot::kUnits, nullptr);
  for (GLenum target : {GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER, GL_QUERY_BUFFER}) glBindBuffer(target, 0);
}

void GlStateSnapshot::restore() const {
  // A host may leave a program (or framebuffer, VAO) current that it already deleted: GL keeps it
  // alive only while bound, so once a pass unbinds it the name is gone and binding it again would
  // raise GL_INVALID_VALUE. Such names restore to 0.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER,
                    drawFramebuffer == 0 || glIsFramebuffer(drawFramebuffer) ? drawFramebuffer : 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER,
                    readFramebuffer == 0 || glIsFramebuffer(readFramebuffer) ? readFramebuffer : 0);
  glUseProgram(program == 0 || glIsProgram(program) ? program : 0);
  glBindVertexArray(vertexArray == 0 || glIsVertexArray(vertexArray) ? vertexArray : 0);
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
  setEnabled(GL_BLEND, blend);
  setEnabled(GL_DEPTH_TEST, depthTest);
  setEnabled(GL_STENCIL_TEST, stencilTest);
  setEnabled(GL_CULL_FACE, cullFace);
  setEnabled(GL_SCISSOR_TEST, scissorTest);
  setEnabled(GL_MULTISAMPLE, multisample);
  setEnabled(GL_SAMPLE_SHADING, sampleShading);
  setEnabled(GL_FRAMEBUFFER_SRGB, framebufferSrgb);
  glDepthMask(depthMask);
  glColorMask(colorMask[0], colorMask[1], colorMask[2], colorMask[3]);
  glBlendFuncSeparate(blendSrcRgb, blendDstRgb, blendSrcAlpha, blendDstAlpha);
  glBlendEquationSeparate(blendEquationRgb, blendEquationAlpha);
  glDepthFunc(depthFunc);
  glCullFace(cullFaceMode);
  glStencilFuncSeparate(GL_FRONT, stencilFunc, stencilRef, stencilValueMask);
  glStencilMaskSeparate(GL_FRONT, stencilWriteMask);
  glStencilOpSeparate(GL_FRONT, stencilFail, stencilPassDepthFail, stencilPassDepthPass);
  glStencilFuncSeparate(GL_BACK, backStencilFunc, backStencilRef, backStencilValueMask);
  glStencilMaskSeparate(GL_BACK, backStencilWriteMask);
  glStencilOpSeparate(GL_BACK, backStencilFail, backStencilPassDepthFail, backStencilPassDepthPass);
  glMinSampleShading(minSampleShading);
  for (int unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, textureBindings2D[unit]);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, textureBindings2DMultisample[unit]);
    glBindSampler(unit, samplerBindings[unit]);
  }
  glActiveTexture(activeTexture);
  for (GLuint unit = 0; unit < imageBindings.size(); ++unit) {
    const ImageBinding& image = imageBindings[unit];
    glBindImageTexture(unit, image.texture == 0 || glIsTexture(GLuint(image.texture)) ? GLuint(image.texture) : 0,
                       image.level, GLboolean(image.layered), image.layer, GLenum(image.access), GLenum(image.format));
  }
  glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
  glPixelStorei(GL_PACK_ROW_LENGTH, packRowLength);
  glPixelStorei(GL_PACK_SKIP_PIXELS, packSkipPixels);
  glPixelStorei(GL_PACK_SKIP_ROWS, packSkipRows);
  restoreBuffers(GL_ATOMIC_COUNTER_BUFFER, atomicCounterBuffers);
  restoreBuffers(GL_SHADER_STORAGE_BUFFER, shaderStorageBuffers);
  restoreBuffers(GL_UNIFORM_BUFFER, uniformBuffers);
  for (size_t i = 0; i < std::size(kPlainBufferTargets); ++i)
    glBindBuffer(kPlainBufferTargets[i], liveBuffer(plainBuffers[i]));
  // Per draw buffer last: the single-value calls above set every draw buffer to buffer 0's.
  for (GLuint i = 0; i < drawBuffers.size(); ++i) {
    const DrawBufferState& d = drawBuffers[i];
    glColorMaski(i, d.colorMask[0], d.colorMask[1], d.colorMask[2], d.colorMask[3]);
    if (d.blend)
      glEnablei(GL_BLEND, i);
    else
      glDisablei(GL_BLEND, i);
    glBlendFuncSeparatei(i, GLenum(d.srcRgb), GLenum(d.dstRgb), GLenum(d.srcAlpha), GLenum(d.dstAlpha));
    glBlendEquationSeparatei(i, GLenum(d.equationRgb), GLenum(d.equationAlpha));
  }
}

bool GlStateSnapshot::operator==(const GlStateSnapshot& o) const {
  return drawFramebuffer == o.drawFramebuffer && readFramebuffer == o.readFramebuffer && program == o.program &&
         vertexArray == o.vertexArray && activeTexture == o.activeTexture && viewport == o.viewport &&
         scissorBox == o.scissorBox && blend == o.blend && depthTest == o.depthTest && stencilTest == o.stencilTest &&
         cullFace == o.cullFace && scissorTest == o.scissorTest && multisample == o.multisample &&
         sampleShading == o.sampleShading && framebufferSrgb == o.framebufferSrgb && depthMask == o.depthMask &&
         colorMask == o.colorMask && blendSrcRgb == o.blendSrcRgb && blendDstRgb == o.blendDstRgb &&
         blendSrcAlpha == o.blendSrcAlpha && blendDstAlpha == o.blendDstAlpha &&
         blendEquationRgb == o.blendEquationRgb && blendEquationAlpha == o.blendEquationAlpha &&
         depthFunc == o.depthFunc && cullFaceMode == o.cullFaceMode && stencilFunc == o.stencilFunc &&
         stencilRef == o.stencilRef && stencilValueMask == o.stencilValueMask &&
         stencilWriteMask == o.stencilWriteMask && stencilFail == o.stencilFail &&
         stencilPassDepthFail == o.stencilPassDepthFail && stencilPassDepthPass == o.stencilPassDepthPass &&
         backStencilFunc == o.backStencilFunc && backStencilRef == o.backStencilRef &&
         backStencilValueMask == o.backStencilValueMask && backStencilWriteMask == o.backStencilWriteMask &&
         backStencilFail == o.backStencilFail && backStencilPassDepthFail == o.backStencilPassDepthFail &&
         backStencilPassDepthPass == o.backStencilPassDepthPass && minSampleShading == o.minSampleShading &&
         textureBindings2D == o.textureBindings2D && textureBindings2DMultisample == o.textureBindings2DMultisample &&
         samplerBindings == o.samplerBindings && imageBindings == o.imageBindings && packAlignment == o.packAlignment &&
         unpackAlignment == o.unpackAlignment && packRowLength == o.packRowLength &&
         packSkipPixels == o.packSkipPixels && packSkipRows == o.packSkipRows && atomicCounterBuffers == o.atomicCounterBuffers &&
         shaderStorageBuffers == o.shaderStorageBuffers && uniformBuffers == o.uniformBuffers &&
         plainBuffers == o.plainBuffers && drawBuffers == o.drawBuffers;
}

}  // namespace retroaa
