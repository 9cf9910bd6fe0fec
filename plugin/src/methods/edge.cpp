// `edge` (Thibieroz) and `per-sample`: the per-pixel slice count from an edge detector.
#include <cmath>
#include <string>

#include "methods.h"

namespace retroaa {

Result<std::unique_ptr<EdgeMask>> EdgeMask::create(PluginContext& context, const MsaaGBuffer& source,
                                                   EdgeDetector detector, bool stencilExport) {
  auto mask = std::make_unique<EdgeMask>();
  mask->detector_ = detector;
  mask->stencilExport_ = stencilExport;
  const std::string defines = source.shaderDefines(context.layout, false) +
                              "#define EDGE_DETECTOR " + std::to_string(int(detector)) + "\n" +
                              "#define STENCIL_EXPORT " + (stencilExport ? "1" : "0") + "\n";
  auto program = context.shaders->program("common/fullscreen.vert", "edge/detect_edges.frag", defines);
  if (!program) return program.error();
  mask->program_ = std::move(program.value());
  return mask;
}

Status EdgeMask::run(PluginContext& context, const MsaaGBuffer& source, SliceRenderer& slices, const FrameInfo& frame) {
  ScopedPass timed(context, "edge_mask");
  const GLuint program = program_.get();
  glUseProgram(program);
  source.bind(context.layout);
  setDepthEncodingUniforms(program, context.layout);
  glUniform1f(glGetUniformLocation(program, "uFootprintTan"), context.footprintTan(frame));
  // A budget scale above 1 marks more pixels: a smaller closeness.
  glUniform1f(glGetUniformLocation(program, "uDepthCloseness"), context.config.edgeDepthCloseness / float(context.budgetScale));
  glUniform1f(glGetUniformLocation(program, "uNormalCosine"),
              std::cos(context.config.edgeNormalAngleDegrees * 3.14159265f / 180.0f));
  return slices.writeMask(context, program, stencilExport_);
}

}  // namespace retroaa
