// `fxaa`: FXAA on the host's display target (shaders/fxaa/).
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
  Result<GlProgram> program =
      context.shaders->program("common/fullscreen.vert", "fxaa/fxaa.frag",
                               "#define FXAA_SEARCH_STEPS " + std::to_string(searchSteps(context.config.fxaaQuality)) + "\n");
  if (!program) return program.error();
  pass->program_ = std::move(program.value());
  return pass;
}

Status FxaaPass::run(PluginContext& context, const PostTarget& post) {
  ScopedPass timed(context, "fxaa");
  const GBufferLayout& layout = context.layout;
  const GLuint program = program_.get();
  post.bindAsOutput(context);
  glUseProgram(program);
  post.bindInput(layout, 0);
  glUniform2f(glGetUniformLocation(program, "uTexelSize"), 1.0f / layout.width, 1.0f / layout.height);
  glUniform1f(glGetUniformLocation(program, "uEdgeThreshold"), context.config.fxaaEdgeThreshold);
  glUniform1f(glGetUniformLocation(program, "uEdgeThresholdMin"), 0.0312f);
  glUniform1f(glGetUniformLocation(program, "uSubpixel"), 0.75f);
  context.drawFullscreen();
  post.copyBack(layout);
  return Status::ok();
}

}  // namespace retroaa
