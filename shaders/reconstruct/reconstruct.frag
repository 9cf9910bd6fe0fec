#version 450 core
// The reconstruction (reconstruct.glsl) as two full-screen draws that render in place
// (MarkedRewrite): RECONSTRUCT_MARK 1 discards every pixel each sub-sample of which lies on its own
// surface (the target already holds it) and leaves the rest marked in a stencil; RECONSTRUCT_MARK 0
// rebuilds the marked pixels alone.
#include "reconstruct/reconstruct.glsl"
out vec4 outColour;

void main() {
#if RECONSTRUCT_MARK
  if (allOnOwnSurface(ivec2(gl_FragCoord.xy))) discard;
#else
  bool changed;  // true: the pixel was marked
  outColour = reconstructPixel(ivec2(gl_FragCoord.xy), changed);
#endif
}
