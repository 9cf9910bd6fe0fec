// Snapshot and restore of every piece of GL state a plugin pass may change. The plugin lives inside
// someone else's renderer (FreeSpace Open keeps a GL state cache): each public call restores all of
// it on return.
#pragma once

#include <epoxy/gl.h>

#include "shared_constants.h"

#include <array>
#include <vector>

namespace retroaa {

struct GlStateSnapshot {
  GLint drawFramebuffer = 0, readFramebuffer = 0, program = 0, vertexArray = 0, activeTexture = 0;
  std::array<GLint, 4> viewport{}, scissorBox{};
  GLboolean blend = 0, depthTest = 0, stencilTest = 0, cullFace = 0, scissorTest = 0, multisample = 0,
            sampleShading = 0, framebufferSrgb = 0, depthMask = 0;
  std::array<GLboolean, 4> colorMask{};
  GLint blendSrcRgb = 0, blendDstRgb = 0, blendSrcAlpha = 0, blendDstAlpha = 0, blendEquationRgb = 0,
        blendEquationAlpha = 0, depthFunc = 0, cullFaceMode = 0;
  GLint stencilFunc = 0, stencilRef = 0, stencilValueMask = 0, stencilWriteMask = 0, stencilFail = 0,
        stencilPassDepthFail = 0, stencilPassDepthPass = 0;
  GLint backStencilFunc = 0, backStencilRef = 0, backStencilValueMask = 0, backStencilWriteMask = 0,
        backStencilFail = 0, backStencilPassDepthFail = 0, backStencilPassDepthPass = 0;
  GLfloat minSampleShading = 0;
  std::vector<GLint> textureBindings2D, textureBindings2DMultisample, samplerBindings;  // per unit
  // The image units the plugin's compute passes write through (0 … kImageUnits - 1, as the context has).
  struct ImageBinding {
    GLint texture = 0, level = 0, layered = 0, layer = 0, access = GL_READ_ONLY, format = GL_R8;
    bool operator==(const ImageBinding& o) const {
      return texture == o.texture && level == o.level && layered == o.layered && layer == o.layer &&
             access == o.access && format == o.format;
    }
  };
  std::vector<ImageBinding> imageBindings;
  GLint packAlignment = 4, unpackAlignment = 4, packRowLength = 0, packSkipPixels = 0, packSkipRows = 0;
  // Buffer bindings: the generic one of each indexed target, and its first kBufferIndices indexed ranges
  // (the plugin's passes bind atomic counters at 0; a host's SSBOs and uniform blocks live there too).
  struct BufferRange {
    GLint buffer = 0;
    GLint64 start = 0, size = 0;  // size 0: the whole buffer (glBindBufferBase)
    bool operator==(const BufferRange& o) const { return buffer == o.buffer && start == o.start && size == o.size; }
  };
  struct IndexedBuffers {
    GLint generic = 0;
    std::vector<BufferRange> ranges;
    bool operator==(const IndexedBuffers& o) const { return generic == o.generic && ranges == o.ranges; }
  };
  IndexedBuffers atomicCounterBuffers, shaderStorageBuffers, uniformBuffers;
  // The plain buffer targets a call may bind or read through: pixel pack and unpack (a readback or upload
  // with one bound goes to that buffer), query results, indirect draws and dispatches, copies.
  static constexpr GLenum kPlainBufferTargets[] = {GL_PIXEL_PACK_BUFFER,      GL_PIXEL_UNPACK_BUFFER,
                                                   GL_QUERY_BUFFER,           GL_DRAW_INDIRECT_BUFFER,
                                                   GL_DISPATCH_INDIRECT_BUFFER, GL_COPY_READ_BUFFER,
                                                   GL_COPY_WRITE_BUFFER,      GL_ARRAY_BUFFER,
                                                   GL_TEXTURE_BUFFER};
  std::array<GLint, std::size(kPlainBufferTargets)> plainBuffers{};
  // Per draw buffer (0 … kDrawBuffers - 1): colour mask, blend enable, blend functions and equations (the
  // single-value queries above are draw buffer 0's).
  static constexpr int kDrawBuffers = 8;
  struct DrawBufferState {
    std::array<GLboolean, 4> colorMask{};
    GLboolean blend = 0;
    GLint srcRgb = 0, dstRgb = 0, srcAlpha = 0, dstAlpha = 0, equationRgb = 0, equationAlpha = 0;
    bool operator==(const DrawBufferState& o) const {
      return colorMask == o.colorMask && blend == o.blend && srcRgb == o.srcRgb && dstRgb == o.dstRgb &&
             srcAlpha == o.srcAlpha && dstAlpha == o.dstAlpha && equationRgb == o.equationRgb &&
             equationAlpha == o.equationAlpha;
    }
  };
  std::vector<DrawBufferState> drawBuffers;

  static constexpr int kUnits = 16;
  static constexpr int kImageUnits = kMaxAttachments + 1;  // the compute resolve's: the attachments and its depth
  static constexpr int kBufferIndices = 4;
  static GlStateSnapshot capture();
  void restore() const;
  bool operator==(const GlStateSnapshot& other) const;
};

// Captures on construction, restores on destruction. In between, units 0–15 have no sampler object:
// the plugin's passes read its textures with their own parameters, whatever sampler a host left bound
// (one with mipmap filtering would make the plugin's single-level textures incomplete, reading zero);
// and no pixel pack, pixel unpack or query buffer is bound, so the plugin's readbacks, uploads and query
// reads reach its own memory, not a buffer the host left bound.
class GlStateGuard {
 public:
  GlStateGuard();
  ~GlStateGuard() { saved_.restore(); }
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  GlStateSnapshot saved_;
};

}  // namespace retroaa
