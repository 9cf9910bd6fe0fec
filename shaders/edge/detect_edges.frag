#version 450 core
// Edge detection for `edge` (Thibieroz): a pixel whose samples see more than one surface (by the chosen
// EDGE_DETECTOR) gets all N samples lit (slice count N), any other pixel one (count 1). Writes the count into an R8UI
// target and, where ARB_shader_stencil_export exists, into the stencil buffer in the same pass.
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/gbuffer.glsl"

uniform float uFootprintTan;  // tan(hfov / width)
layout(location = 0) out uint outCount;
#include "edge/detector.glsl"

void main() {
  int count = isEdge(min(ivec2(gl_FragCoord.xy), gbufferPixels() - 1)) ? SAMPLES : 1;
  outCount = uint(count);
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
