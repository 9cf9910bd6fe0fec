// `adaptive` (Holländer et al., JCGT 2013) through slices: k samples where the metrics ask for them.
#include <cmath>
#include <limits>
#include <string>

#include "methods.h"

namespace retroaa {

std::vector<int> spreadingSampleOrder(const std::vector<float>& positionsXY) {
  const int n = int(positionsXY.size() / 2);
  std::vector<int> order;
  std::vector<bool> taken(n, false);
  auto distance2 = [&](int a, float x, float y) {
    const float dx = positionsXY[2 * a] - x, dy = positionsXY[2 * a + 1] - y;
    return dx * dx + dy * dy;
  };
  while (int(order.size()) < n) {
    int best = -1;
    float bestScore = -1.0f;
    for (int candidate = 0; candidate < n; ++candidate) {
      if (taken[candidate]) continue;
      // First: nearest the centre. Then: farthest from every sample already taken.
      float score;
      if (order.empty()) {
        score = -distance2(candidate, 0.5f, 0.5f);
      } else {
        score = std::numeric_limits<float>::max();
        for (int t : order) score = std::min(score, distance2(candidate, positionsXY[2 * t], positionsXY[2 * t + 1]));
      }
      if (best < 0 || score > bestScore) best = candidate, bestScore = score;
    }
    taken[best] = true;
    order.push_back(best);
  }
  return order;
}

Result<std::unique_ptr<AdaptivePass>> AdaptivePass::create(PluginContext& context, const MsaaGBuffer& source,
                                                           bool stencilExport) {
  auto pass = std::make_unique<AdaptivePass>();
  const GBufferLayout& layout = context.layout;
  pass->stencilExport_ = stencilExport;
  auto geometry = context.shaders->program("common/fullscreen.vert", "adaptive/geometry_metric.frag",
                                           source.shaderDefines(layout, false));
  if (!geometry) return geometry.error();
  pass->geometryProgram_ = std::move(geometry.value());
  auto shading = context.shaders->program("common/fullscreen.vert", "adaptive/shading_metric.frag",
                                          "#define SAMPLES " + std::to_string(source.samples()) + "\n#define STENCIL_EXPORT " +
                                              (stencilExport ? "1" : "0") + "\n");
  if (!shading) return shading.error();
  pass->shadingProgram_ = std::move(shading.value());
  pass->geometryK_ = makeTexture(context, GL_R16F, layout.width, layout.height, 0, "adaptive.geometry_k", pass->bytes_);
  pass->geometryTarget_ = makeFramebuffer(context, "adaptive.geometry_k");
  glNamedFramebufferTexture(pass->geometryTarget_.get(), GL_COLOR_ATTACHMENT0, pass->geometryK_.get(), 0);
  if (Status status = checkFramebuffer(pass->geometryTarget_.get(), "adaptive.geometry_k"); !status) return status.error();

  // The driver's own sample positions decide the order (queried, not assumed).
  std::vector<float> positions(size_t(source.samples()) * 2, 0.5f);
  if (source.multisampled()) readSamplePositions(source.framebuffer(), positions);
  pass->order_ = spreadingSampleOrder(positions);
  return pass;
}

Status AdaptivePass::measureGeometry(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame) {
  ScopedPass timed(context, "adaptive.geometry_metric");
  const GBufferLayout& layout = context.layout;
  const GLuint program = geometryProgram_.get();
  context.beginFullscreenPass(geometryTarget_.get());
  glUseProgram(program);
  source.bind(layout);
  setDepthEncodingUniforms(program, layout);
  glUniform1f(glGetUniformLocation(program, "uFootprintTan"), context.footprintTan(frame));
  const float budget = float(context.budgetScale);  // 1 without a budget
  glUniform1f(glGetUniformLocation(program, "uDepthScale"), context.config.adaptiveDepthScale * budget);
  glUniform1f(glGetUniformLocation(program, "uNormalScale"), context.config.adaptiveNormalScale * budget);
  context.drawFullscreen();
  return Status::ok();
}

SliceRenderer::Plan AdaptivePass::plan(PluginContext& context, SliceRenderer& slices) {
  SliceRenderer::Plan plan;
  plan.sampleOrder = order_;
  plan.firstSliceEverywhere = true;  // the paper lights one sample of every pixel first
  plan.maskAfterFirstSlice = [this, &context, &slices]() {
    ScopedPass timed(context, "adaptive.shading_metric");
    const GLuint program = shadingProgram_.get();
    glUseProgram(program);
    glBindTextureUnit(0, slices.firstSliceLight());
    glBindTextureUnit(2, geometryK_.get());
    glUniform1f(glGetUniformLocation(program, "uShadingScale"), context.config.adaptiveShadingScale * float(context.budgetScale));
    glUniform1f(glGetUniformLocation(program, "uThresholdMin"), context.config.adaptiveThresholdMin);
    glUniform1f(glGetUniformLocation(program, "uThresholdEdge"), context.config.adaptiveThresholdEdge);
    glUniform1i(glGetUniformLocation(program, "uMinSamples"), context.config.adaptiveMinSamples);
    return slices.writeMask(context, program, stencilExport_);
  };
  return plan;
}

}  // namespace retroaa
