#version 450 core
// The restore after the slices (ResolvePass::restore) in one pass: the host's attachments as shade() found
// them (keepForRestore's copies) written back, and with RESTORE_DEPTH_FLOATS the resolve's depth floats
// through gl_FragDepth, as the resolve wrote them (the host's stencil untouched). One draw rather than a
// copy per attachment and a depth pass: a copy makes llvmpipe finish the frame's binned draws first.
layout(binding = 0) uniform sampler2D uKept[ATTACHMENT_COUNT];
#ifdef RESTORE_DEPTH_FLOATS
layout(binding = ATTACHMENT_COUNT) uniform sampler2D uResolvedDepth;
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 values[ATTACHMENT_COUNT];
#define FETCH_KEPT(a) values[a] = texelFetch(uKept[a], pixel, 0);
  FOR_EACH_ATTACHMENT(FETCH_KEPT)
  STORE_OUTPUTS(values);
#ifdef RESTORE_DEPTH_FLOATS
  gl_FragDepth = texelFetch(uResolvedDepth, pixel, 0).r;
#endif
}
