// `aggregate` (Crassin et al., "Aggregate G-Buffer Anti-Aliasing", 2016) retrofitted: clustering and
// aggregate attributes are computed from the MSAA G-buffer, and each aggregate is a slice the host's
// unchanged lighting lights once.
#include <cmath>
#include <string>

#include "methods.h"

namespace retroaa {

Result<std::unique_ptr<AggregatePass>> AggregatePass::create(PluginContext& context, const MsaaGBuffer& source,
                                                             SliceRenderer& slices, bool stencilExport) {
  auto pass = std::make_unique<AggregatePass>();
  const GBufferLayout& layout = context.layout;
  pass->stencilExport_ = stencilExport;
  const int maxAggregates = std::min(context.config.aggregateCount, source.samples());
  auto cluster = context.shaders->program(
      "common/fullscreen.vert", "aggregate/cluster.frag",
      source.shaderDefines(layout, false) + "#define MAX_AGGREGATES " + std::to_string(maxAggregates) +
          "\n#define STENCIL_EXPORT " + (stencilExport ? "1" : "0") + "\n");
  if (!cluster) return cluster.error();
  pass->clusterProgram_ = std::move(cluster.value());
  auto write = context.shaders->program("common/fullscreen.vert", "aggregate/write_aggregate.frag", source.shaderDefines(layout));
  if (!write) return write.error();
  pass->writeProgram_ = std::move(write.value());

  pass->assignment_ = makeTexture(context, GL_RG32UI, layout.width, layout.height, 0, "aggregate.assignment", pass->bytes_);
  pass->clusterTarget_ = makeFramebuffer(context, "aggregate.cluster");
  const GLuint fbo = pass->clusterTarget_.get();
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, slices.counts(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, pass->assignment_.get(), 0);
  glNamedFramebufferTexture(fbo, GL_DEPTH_STENCIL_ATTACHMENT, slices.mask(), 0);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo, 2, drawBuffers);
  if (Status status = checkFramebuffer(fbo, "aggregate.cluster"); !status) return status.error();

  pass->samplePositions_.assign(size_t(source.samples()) * 2, 0.5f);
  if (source.multisampled()) readSamplePositions(source.framebuffer(), pass->samplePositions_);
  return pass;
}

Status AggregatePass::cluster(PluginContext& context, const MsaaGBuffer& source, SliceRenderer& slices,
                              const FrameInfo& frame) {
  ScopedPass timed(context, "aggregate.cluster");
  const GLuint program = clusterProgram_.get();
  glUseProgram(program);
  source.bind(context.layout);
  setDepthEncodingUniforms(program, context.layout);
  glUniform1f(glGetUniformLocation(program, "uFootprintTan"), context.footprintTan(frame));
  glUniform1f(glGetUniformLocation(program, "uLength"), context.config.aggregateLength);
  glUniform1f(glGetUniformLocation(program, "uThreshold"), context.config.aggregateThreshold);
  glUniform2fv(glGetUniformLocation(program, "uSamplePositions"), source.samples(), samplePositions_.data());
  return slices.writeMask(context, program, stencilExport_, clusterTarget_.get());
}

SliceRenderer::Plan AggregatePass::plan(PluginContext& context, const MsaaGBuffer& source) {
  SliceRenderer::Plan plan;
  plan.firstSliceEverywhere = true;  // aggregate 0 replaces the resolved value of every pixel
  plan.sliceCount = std::min(context.config.aggregateCount, source.samples()) + 1;  // + background
  plan.writeProgram = writeProgram_.get();
  plan.coverageAssignment = assignment_.get();
  const GlossEncoding gloss = context.layout.glossEncoding;
  const GLuint program = writeProgram_.get();
  const GBufferLayout& layout = context.layout;
  plan.bindWriteInputs = [this, program, gloss, &layout]() {
    glBindTextureUnit(14, assignment_.get());
    setDepthEncodingUniforms(program, layout);
    glUniform1i(glGetUniformLocation(program, "uHasGloss"), gloss.present ? 1 : 0);
    glUniform1f(glGetUniformLocation(program, "uGlossScale"), gloss.log2ExponentScale);
    glUniform1f(glGetUniformLocation(program, "uGlossBias"), gloss.log2ExponentBias);
  };
  return plan;
}

}  // namespace retroaa
