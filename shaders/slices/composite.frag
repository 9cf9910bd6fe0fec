#version 450 core
// Adds weight × light(slice) into the host's light target. Weight: 1 / (the pixel's slice count), or,
// for aggregates, the fraction of the pixel's usable samples that belong to this slice.
layout(binding = 0) uniform sampler2D uSliceLight;
layout(binding = 1) uniform usampler2D uSliceCounts;
#include "aggregate/aggregate.glsl"
uniform int uSlice;
uniform int uCoverageWeights;  // 0: 1 / count; 1: from the aggregate assignment
uniform int uSamples;
out vec4 outLight;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float weight = 1.0 / float(max(texelFetch(uSliceCounts, pixel, 0).r, 1u));
  if (uCoverageWeights != 0) {
    uvec2 assignment = texelFetch(uAssignment, pixel, 0).xy;
    float mine = 0.0, usable = 0.0;
    for (int s = 0; s < uSamples; ++s) {
      uint slice = sliceOfSample(assignment, s);
      mine += slice == uint(uSlice) ? 1.0 : 0.0;
      usable += slice != 15u ? 1.0 : 0.0;
    }
    weight = usable > 0.0 ? mine / usable : (uSlice == 0 ? 1.0 : 0.0);
  }
  outLight = vec4(texelFetch(uSliceLight, pixel, 0).rgb * weight, weight);
}
