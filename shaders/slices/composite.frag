#version 450 core
// Adds weight × light(slice) into the host's light target, weight = 1 / (the pixel's slice count).
// A technique with other weights supplies its own composite program (SliceRenderer::Plan), reading
// the same inputs plus whatever it binds to UNIT_SLICE_WEIGHTS.
layout(binding = 0) uniform sampler2D uSliceLight;
layout(binding = 1) uniform usampler2D uSliceCounts;
out vec4 outLight;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float weight = 1.0 / float(max(texelFetch(uSliceCounts, pixel, 0).r, 1u));
  outLight = vec4(texelFetch(uSliceLight, pixel, 0).rgb * weight, weight);
}
