#version 450 core
// Where stencil export is missing: colour writes are off, the stencil write mask holds one bit, and
// this pass keeps the pixels whose count has that bit, so that ⌈log2(N+1)⌉ passes spell the count.
layout(binding = 1) uniform usampler2D uSliceCounts;
uniform int uBit;
void main() {
  if ((int(texelFetch(uSliceCounts, ivec2(gl_FragCoord.xy), 0).r) & uBit) == 0) discard;
}
