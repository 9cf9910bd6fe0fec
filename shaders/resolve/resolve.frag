#version 450 core
// The resolve (resolve.glsl) as a full-screen pass: the host's attachments through the outputs, its
// depth through gl_FragDepth.
#include "resolve/resolve.glsl"

void main() {
  vec4 values[ATTACHMENT_COUNT];
  float depth;
  resolvePixel(ivec2(gl_FragCoord.xy), values, depth);
  STORE_OUTPUTS(values);
  // The restore after the slices (RESOLVE_RESTORE) leaves the depth as it is: without a depth output the
  // stencil test that limits it to the slices' pixels runs before the shader.
#ifndef RESOLVE_RESTORE
  gl_FragDepth = depth;
#endif
}
