// `fxaa`: FXAA on the host's display target (shaders/fxaa/). Renders into a plugin-owned copy and
// copies the result back, so the host keeps its own texture.
#include <string>

#include "methods.h"

namespace retroaa {

namespace {
int searchSteps(FxaaQuality quality) {
  switch (quality) {
    case FxaaQuality::Low: return 3;
    case FxaaQuality::Medium: return 6;
    case FxaaQuality::High: return 12;
  }
  return 12;
}
}  // namespace

Result<std::unique_ptr<FxaaPass>> FxaaPass::create(PluginContext& context) {
  auto pass = std::make_unique<FxaaPass>();
  const GBufferLayout& layout = context.layout;
  Result<GlProgram> program =
      context.shaders->program("common/fullscreen.vert", "fxaa/fxaa.frag",
                               "#define FXAA_SEARCH_STEPS " + std::to_string(searchSteps(context.config.fxaaQuality)) + "\n");
  if (!program) return program.error();
  pass->program_ = std::move(program.value());
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  pass->linear_ = GlSampler(context.objects, sampler);
  pass->output_ = makeTexture(context, GL_RGBA8, layout.width, layout.height, 0, "fxaa.output", pass->bytes_);
  pass->outputFramebuffer_ = makeFramebuffer(context, "fxaa.output");
  glNamedFramebufferTexture(pass->outputFramebuffer_.get(), GL_COLOR_ATTACHMENT0, pass->output_.get(), 0);
  if (Status status = checkFramebuffer(pass->outputFramebuffer_.get(), "fxaa.output"); !status) return status.error();
  return pass;
}

Status FxaaPass::run(PluginContext& context) {
  ScopedPass timed(context, "fxaa");
  const GBufferLayout& layout = context.layout;
  const GLuint program = program_.get();
  glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer_.get());
  glViewport(0, 0, layout.width, layout.height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUseProgram(program);
  glBindTextureUnit(0, layout.displayTexture);
  glBindSampler(0, linear_.get());
  glUniform2f(glGetUniformLocation(program, "uTexelSize"), 1.0f / layout.width, 1.0f / layout.height);
  glUniform1f(glGetUniformLocation(program, "uEdgeThreshold"), context.config.fxaaEdgeThreshold);
  glUniform1f(glGetUniformLocation(program, "uEdgeThresholdMin"), 0.0312f);
  glUniform1f(glGetUniformLocation(program, "uSubpixel"), 0.75f);
  context.drawFullscreen();
  glCopyImageSubData(output_.get(), GL_TEXTURE_2D, 0, 0, 0, 0, layout.displayTexture, GL_TEXTURE_2D, 0, 0, 0, 0,
                     layout.width, layout.height, 1);
  return Status::ok();
}

}  // namespace retroaa
