#version 450 core
// Colour writes are off: this pass only exists for the stencil test and the occlusion query
// (pixels lit in a slice), and, with discard, to raise stencil counts where stencil export is missing.
layout(binding = 1) uniform usampler2D uSliceCounts;
uniform int uAtLeast;  // discard pixels whose count is below this (0: keep every pixel)
void main() {
  if (int(texelFetch(uSliceCounts, ivec2(gl_FragCoord.xy), 0).r) < uAtLeast) discard;
}
