// The plugin's techniques. Each lives in one source file here and one folder of shaders/
// (bgfx's one-technique-one-place); each owns its GL objects and frees them in its destructor.
#pragma once

#include "../context.h"

namespace retroaa {

// The multisampled mirror of the host's G-buffer: same attachments and formats, N samples, plus a
// multisampled depth-stencil. The host's model pass renders into it unchanged. N = 1 allocates plain
// single-sample textures (a "multisample" texture of one sample may rasterise at a corner sample
// position, or be backed by more samples), so the resolve at N = 1 sees exactly what `off` sees.
class MsaaGBuffer {
 public:
  static Result<std::unique_ptr<MsaaGBuffer>> create(PluginContext& context, int samples);
  GLuint framebuffer() const { return framebuffer_.get(); }
  GLuint attachment(size_t i) const { return attachments_[i].get(); }
  GLuint depthStencil() const { return depthStencil_.get(); }
  int samples() const { return samples_; }  // as allocated by the driver (may exceed the request)
  bool multisampled() const { return samples_ > 1 || multisampledStorage_; }
  // The #defines shaders reading this G-buffer need (shaders/common/gbuffer.glsl): sample count,
  // attachment roles, depth encoding, and one output per host attachment with STORE_OUTPUTS(values).
  std::string shaderDefines(const GBufferLayout& layout) const;
  // Binds attachment i to texture unit i and the depth-stencil to unit 15.
  void bind(const GBufferLayout& layout) const;
  uint64_t bytes() const { return bytes_; }

 private:
  std::vector<GlTexture> attachments_;
  GlTexture depthStencil_;
  GlFramebuffer framebuffer_;
  int samples_ = 1;
  bool multisampledStorage_ = false;
  uint64_t bytes_ = 0;
};

void setDepthEncodingUniforms(GLuint program, const GBufferLayout& layout);

// `resolve`: the depth-aware resolve of Magnussen (and FreeSpace Open's variant) from the MSAA
// G-buffer into the host's single-sample G-buffer and depth.
class ResolvePass {
 public:
  static Result<std::unique_ptr<ResolvePass>> create(PluginContext& context, const MsaaGBuffer& source);
  Status run(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame);

 private:
  GlProgram program_;
  GlFramebuffer hostTarget_;  // the host's attachments + depth, without its stencil bits
};

// `fxaa`: Lottes' FXAA 3.11 (quality variant) on the tonemapped display target.
class FxaaPass {
 public:
  static Result<std::unique_ptr<FxaaPass>> create(PluginContext& context);
  Status run(PluginContext& context);
  uint64_t bytes() const { return bytes_; }

 private:
  GlProgram program_;
  GlSampler linear_;
  GlTexture output_;
  GlFramebuffer outputFramebuffer_;
  uint64_t bytes_ = 0;
};

}  // namespace retroaa
