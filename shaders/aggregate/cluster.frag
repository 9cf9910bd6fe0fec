#version 450 core
// Aggregate G-buffer anti-aliasing (Crassin et al. 2016), Algorithm 1, run on the MSAA G-buffer:
// group each pixel's geometry samples into at most MAX_AGGREGATES aggregates. Distance between samples
//   D(a, b) = |Δp / k|² + (1 − n_a · n_b) / 2,
// p from view depth and the sample's position in the pixel, k = aggregate_length pixel footprints at
// the pixel's mean depth (so 1 m and 100 km behave alike). Seeds: the sample farthest from the mean,
// then the one farthest from it, then the one with the largest sum of squared distances to the seeds;
// a seed is taken only if it is farther than t from every seed so far. Every sample joins its nearest
// seed. Background samples form one extra slice of their own; samples with NaN/Inf join none.
// Writes the slice count, and each sample's slice index in 4 bits (15: none).
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/gbuffer.glsl"
uniform float uFootprintTan;
uniform float uLength;     // k, in pixel footprints
uniform float uThreshold;  // t
uniform vec2 uSamplePositions[SAMPLES];
layout(location = 0) out uint outCount;
layout(location = 1) out uvec2 outAssignment;

vec3 position[SAMPLES];
vec3 normal[SAMPLES];
float scale = 1.0;  // k in metres, set per pixel

float sampleDistance2(vec3 pa, vec3 na, vec3 pb, vec3 nb) {
  vec3 dp = (pa - pb) / scale;
  return dot(dp, dp) + (1.0 - dot(na, nb)) * 0.5;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int kind[SAMPLES];  // 0 geometry, 1 background, 2 unusable
  int geometry = 0;
  vec3 meanPosition = vec3(0.0), normalSum = vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    kind[s] = !sampleIsFinite(pixel, s) ? 2 : (isinf(d) ? 1 : 0);
    if (kind[s] != 0) continue;
    vec2 offset = (uSamplePositions[s] - 0.5) * d * uFootprintTan;
    position[s] = vec3(offset, d);
    vec3 n = sampleNormal(pixel, s);
    normal[s] = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
    meanPosition += position[s];
    normalSum += normal[s];
    ++geometry;
  }

  int seeds[MAX_AGGREGATES];
  int seedCount = 0;
  if (geometry > 0) {
    meanPosition /= float(geometry);
    vec3 meanNormal = dot(normalSum, normalSum) > 0.0 ? normalize(normalSum) : vec3(0.0, 0.0, 1.0);
    scale = max(uLength * meanPosition.z * uFootprintTan, 1e-30);
    float best = -1.0;
    for (int s = 0; s < SAMPLES; ++s)  // 1. farthest from the mean
      if (kind[s] == 0 && sampleDistance2(position[s], normal[s], meanPosition, meanNormal) > best) {
        best = sampleDistance2(position[s], normal[s], meanPosition, meanNormal);
        seeds[0] = s;
      }
    seedCount = 1;
    for (int a = 1; a < MAX_AGGREGATES; ++a) {  // 2. farthest from the first; 3. largest sum of squares
      int candidate = -1;
      float candidateScore = -1.0;
      for (int s = 0; s < SAMPLES; ++s) {
        if (kind[s] != 0) continue;
        float nearest = 1.0 / 0.0, score = 0.0;
        for (int j = 0; j < seedCount; ++j) {
          float dist = sampleDistance2(position[s], normal[s], position[seeds[j]], normal[seeds[j]]);
          nearest = min(nearest, dist);
          score += dist * dist;
        }
        if (a == 1) score = nearest;
        if (nearest > uThreshold && score > candidateScore) {
          candidateScore = score;
          candidate = s;
        }
      }
      if (candidate < 0) break;
      seeds[seedCount++] = candidate;
    }
  }

  bool anyBackground = false;
  uvec2 assignment = uvec2(0u);
  for (int s = 0; s < SAMPLES; ++s) {
    uint slice = NO_SLICE;
    if (kind[s] == 0) {
      float nearest = 1.0 / 0.0;
      for (int j = 0; j < seedCount; ++j) {
        float dist = sampleDistance2(position[s], normal[s], position[seeds[j]], normal[seeds[j]]);
        if (dist < nearest) nearest = dist, slice = uint(j);
      }
    } else if (kind[s] == 1) {
      slice = uint(seedCount);
      anyBackground = true;
    }
    if (s < 8) assignment.x |= slice << uint(4 * s); else assignment.y |= slice << uint(4 * (s - 8));
  }
  int count = max(seedCount + (anyBackground ? 1 : 0), 1);
  outCount = uint(count);
  outAssignment = assignment;
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
