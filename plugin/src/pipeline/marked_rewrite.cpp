// MarkedRewrite: a cheap test on every pixel marks a stencil; the costly rewrite runs on the marked ones.
#include "pipeline.h"

namespace retroaa {

Result<MarkedRewrite> MarkedRewrite::create(PluginContext& context, GLuint output, const std::string& label,
                                            uint64_t& bytes) {
  MarkedRewrite pass;
  const GBufferLayout& layout = context.layout;
  pass.marked_ =
      makeTexture(context, GL_STENCIL_INDEX8, layout.width, layout.height, 0, (label + ".marked").c_str(), bytes);
  pass.markTarget_ = makeFramebuffer(context, (label + ".mark").c_str());  // the stencil alone
  glNamedFramebufferTexture(pass.markTarget_.get(), GL_STENCIL_ATTACHMENT, pass.marked_.get(), 0);
  glNamedFramebufferDrawBuffer(pass.markTarget_.get(), GL_NONE);
  pass.rewriteTarget_ = makeFramebuffer(context, (label + ".rewrite").c_str());
  glNamedFramebufferTexture(pass.rewriteTarget_.get(), GL_COLOR_ATTACHMENT0, output, 0);
  glNamedFramebufferTexture(pass.rewriteTarget_.get(), GL_STENCIL_ATTACHMENT, pass.marked_.get(), 0);
  for (const GLuint framebuffer : {pass.markTarget_.get(), pass.rewriteTarget_.get()})
    if (Status status = checkFramebuffer(framebuffer, label.c_str()); !status) return status.error();
  return pass;
}

void MarkedRewrite::run(const PluginContext& context, const ShaderProgram& mark, const ShaderProgram& rewrite,
                        const std::function<void(const ShaderProgram&)>& bind) const {
  context.beginFullscreenPass(markTarget_.get());
  const GLint unmarked = 0;
  glStencilMask(0xFF);  // clears obey the write mask
  glClearNamedFramebufferiv(markTarget_.get(), GL_STENCIL, 0, &unmarked);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  bind(mark);
  context.drawFullscreen();

  context.beginFullscreenPass(rewriteTarget_.get());
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  bind(rewrite);
  context.drawFullscreen();
  glDisable(GL_STENCIL_TEST);
}

}  // namespace retroaa
