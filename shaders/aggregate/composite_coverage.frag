#version 450 core
// The slice composite of `aggregate`: weight × light(slice) into the host's light target, the weight
// being the fraction of the pixel's usable samples that belong to this slice (aggregate `uSlice`).
layout(binding = 0) uniform sampler2D uSliceLight;
#include "aggregate/aggregate.glsl"
uniform int uSlice;
uniform int uSamples;
out vec4 outLight;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uvec2 assignment = texelFetch(uAssignment, pixel, 0).xy;
  float mine = 0.0, usable = 0.0;
  for (int s = 0; s < uSamples; ++s) {
    uint slice = sliceOfSample(assignment, s);
    mine += slice == uint(uSlice) ? 1.0 : 0.0;
    usable += slice != NO_SLICE ? 1.0 : 0.0;
  }
  float weight = usable > 0.0 ? mine / usable : (uSlice == 0 ? 1.0 : 0.0);
  outLight = vec4(texelFetch(uSliceLight, pixel, 0).rgb * weight, weight);
}
