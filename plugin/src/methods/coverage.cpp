// `coverage` (Pettineo, "Deferred MSAA"): no lighting per sample; one filter pass after tonemapping
// blends silhouette pixels by the depth sub-samples' coverage (shaders/coverage/).
#include <cmath>
#include <string>

#include "methods.h"

namespace retroaa {

Result<std::unique_ptr<CoveragePass>> CoveragePass::create(PluginContext& context, const MsaaGBuffer* resolveDepth,
                                                           int samples) {
  auto pass = std::make_unique<CoveragePass>();
  const GBufferLayout& layout = context.layout;
  GLuint framebuffer = 0;
  if (resolveDepth) {
    pass->sampleDepth_ = resolveDepth->depthStencil();
    pass->samples_ = resolveDepth->samples();
    framebuffer = resolveDepth->framebuffer();
  } else {
    pass->depth_ = makeTexture(context, GL_DEPTH24_STENCIL8, layout.width, layout.height, std::max(samples, 1),
                               "coverage.depth", pass->bytes_);
    pass->prepass_ = makeFramebuffer(context, "coverage.prepass");
    glNamedFramebufferTexture(pass->prepass_.get(), GL_DEPTH_STENCIL_ATTACHMENT, pass->depth_.get(), 0);
    glNamedFramebufferDrawBuffer(pass->prepass_.get(), GL_NONE);
    if (Status status = checkFramebuffer(pass->prepass_.get(), "coverage.prepass"); !status) return status.error();
    glGetTextureLevelParameteriv(pass->depth_.get(), 0, GL_TEXTURE_SAMPLES, &pass->samples_);
    pass->sampleDepth_ = pass->depth_.get();
    framebuffer = pass->prepass_.get();
  }
  pass->samplePositions_.assign(size_t(pass->samples_) * 2, 0.5f);
  readSamplePositions(framebuffer, pass->samplePositions_);
  const bool logarithmic = layout.depthBufferEncoding == DepthBufferEncoding::Logarithmic;
  auto program = context.shaders->program("common/fullscreen.vert", "coverage/coverage_filter.frag",
                                          "#define SAMPLES " + std::to_string(pass->samples_) +
                                              "\n#define LOGARITHMIC_DEPTH " + (logarithmic ? "1" : "0") + "\n");
  if (!program) return program.error();
  pass->program_ = std::move(program.value());
  return pass;
}

Status CoveragePass::run(PluginContext& context, const PostTarget& post, const FrameInfo& frame) {
  ScopedPass timed(context, "coverage_filter");
  const GBufferLayout& layout = context.layout;
  const GLuint program = program_.get();
  post.bindAsOutput(context);
  glUseProgram(program);
  post.bindInput(layout, 0);
  glBindTextureUnit(1, layout.depthStencilTexture);
  glBindTextureUnit(2, sampleDepth_);
  glUniform2fv(glGetUniformLocation(program, "uSamplePositions"), samples_, samplePositions_.data());
  glUniform2f(glGetUniformLocation(program, "uTexelSize"), 1.0f / layout.width, 1.0f / layout.height);
  glUniform1f(glGetUniformLocation(program, "uNear"), frame.nearPlane);
  glUniform1f(glGetUniformLocation(program, "uFar"), frame.farPlane);
  glUniform1f(glGetUniformLocation(program, "uFootprintTan"), context.footprintTan(frame));
  glUniform1f(glGetUniformLocation(program, "uTolerance"), context.config.coverageTolerance);
  context.drawFullscreen();
  post.copyBack(layout);
  return Status::ok();
}

}  // namespace retroaa
