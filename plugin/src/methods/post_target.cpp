// The post passes' render target: they read the host's display texture and write a copy of it.
#include "methods.h"

namespace retroaa {

Result<std::unique_ptr<PostTarget>> PostTarget::create(PluginContext& context) {
  auto target = std::make_unique<PostTarget>();
  const GBufferLayout& layout = context.layout;
  target->output_ = makeTexture(context, GL_RGBA8, layout.width, layout.height, 0, "post.output", target->bytes_);
  target->framebuffer_ = makeFramebuffer(context, "post.output");
  glNamedFramebufferTexture(target->framebuffer_.get(), GL_COLOR_ATTACHMENT0, target->output_.get(), 0);
  if (Status status = checkFramebuffer(target->framebuffer_.get(), "post.output"); !status) return status.error();
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  target->linear_ = GlSampler(context.objects, sampler);
  return target;
}

void PostTarget::bindAsOutput(const PluginContext& context) const { context.beginFullscreenPass(framebuffer_.get()); }

void PostTarget::bindInput(const GBufferLayout& layout, GLuint unit) const {
  glBindTextureUnit(unit, layout.displayTexture);
  glBindSampler(unit, linear_.get());
}

void PostTarget::copyBack(const GBufferLayout& layout) const {
  glCopyImageSubData(output_.get(), GL_TEXTURE_2D, 0, 0, 0, 0, layout.displayTexture, GL_TEXTURE_2D, 0, 0, 0, 0,
                     layout.width, layout.height, 1);
}

}  // namespace retroaa
