#version 450 core
// The reconstruction (reconstruct.glsl) as a full-screen pass. It renders in place: a pixel every
// sub-sample of which lies on its own surface is discarded, and the target already holds it.
#include "reconstruct/reconstruct.glsl"
out vec4 outColour;

void main() {
  bool changed;
  outColour = reconstructPixel(ivec2(gl_FragCoord.xy), changed);
  if (!changed) discard;
}
