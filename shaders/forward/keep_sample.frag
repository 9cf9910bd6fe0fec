#version 450 core
// During the slices: the slice's colour into the one sample it lit (uSample), where the pixel's slice
// count says this slice ran (at least uMinCount), alpha 1 marking the sample as kept for fill.frag.
layout(binding = 0) uniform sampler2D uSliceColour;
layout(binding = 1) uniform usampler2D uSliceCounts;
uniform int uMinCount;
uniform int uSample;
out vec4 outColour;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (int(texelFetch(uSliceCounts, pixel, 0).r) < uMinCount) discard;
  gl_SampleMask[0] = 1 << uSample;
  outColour = vec4(texelFetch(uSliceColour, pixel, 0).rgb, 1.0);
}
