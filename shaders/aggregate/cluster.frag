#version 450 core
// Aggregate G-buffer anti-aliasing (Crassin et al. 2016), Algorithm 1, run on the MSAA G-buffer:
// group each pixel's geometry samples into at most MAX_AGGREGATES aggregates. Distance between samples
//   D(a, b) = |Δp / k|² + (1 − n_a · n_b) / 2,
// p from view depth and the sample's position in the pixel, k = aggregate_length pixel footprints at
// the pixel's mean depth (so 1 m and 100 km behave alike). Seeds: the sample farthest from the mean,
// then the one farthest from it, then the one with the largest sum of squared distances to the seeds;
// a seed is taken only if it is farther than t from every seed so far. Every sample joins its nearest
// seed. Background samples form one extra slice of their own; samples with NaN/Inf join none.
// Writes the slice count, and each sample's slice index (aggregate/aggregate.glsl); a pixel of one
// aggregate whose samples agree on the normal (or all background) is marked RESOLVE_HOLDS_AGGREGATE: the
// depth-aware resolve already wrote its mean (MSAA shades a primitive once per pixel), so the slice
// writer skips it.
//
// Each sample's distance to the seeds is kept as they are taken (the nearest, its seed, the sum of
// squares), so every array is indexed by the unrolled sample loop alone: no index read from another
// array, which a SIMD rasteriser (llvmpipe) turns into a scratch-memory gather per lane.
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/gbuffer.glsl"
#include "aggregate/aggregate.glsl"
uniform float uFootprintTan;
uniform float uLength;     // k, in pixel footprints
uniform float uThreshold;  // t
uniform vec2 uSamplePositions[SAMPLES];
layout(location = 0) out uint outCount;
layout(location = 1) out uvec2 outAssignment;

float scale = 1.0;  // k in metres, set per pixel

float sampleDistance2(vec3 pa, vec3 na, vec3 pb, vec3 nb) {
  vec3 dp = (pa - pb) / scale;
  return dot(dp, dp) + (1.0 - dot(na, nb)) * 0.5;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 position[SAMPLES];
  vec3 normal[SAMPLES];
  int kind[SAMPLES];  // 0 geometry, 1 background, 2 unusable
  int geometry = 0;
  bool normalsAgree = true;  // every geometry sample's normal equal to the first's
  vec3 firstNormal = vec3(0.0);
  vec3 meanPosition = vec3(0.0), normalSum = vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    kind[s] = !sampleIsFinite(pixel, s) ? 2 : (isinf(d) ? 1 : 0);
    position[s] = vec3(0.0);
    normal[s] = vec3(0.0, 0.0, 1.0);
    if (kind[s] == 0) {  // an `if`, not `continue` (docs/architecture.md)
      vec2 offset = (uSamplePositions[s] - 0.5) * d * uFootprintTan;
      position[s] = vec3(offset, d);
      vec3 n = sampleNormal(pixel, s);
      normal[s] = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
      if (geometry == 0) firstNormal = normal[s];
      normalsAgree = normalsAgree && normal[s] == firstNormal;
      meanPosition += position[s];
      normalSum += normal[s];
      ++geometry;
    }
  }

  float nearest[SAMPLES];   // to the nearest seed so far
  float sumSquares[SAMPLES];  // of the distances to the seeds so far
  uint seedOf[SAMPLES];     // that nearest seed
  for (int s = 0; s < SAMPLES; ++s) nearest[s] = 1.0 / 0.0, sumSquares[s] = 0.0, seedOf[s] = NO_SLICE;
  int seedCount = 0;
  if (geometry > 0) {
    meanPosition /= float(geometry);
    vec3 meanNormal = dot(normalSum, normalSum) > 0.0 ? normalize(normalSum) : vec3(0.0, 0.0, 1.0);
    scale = max(uLength * meanPosition.z * uFootprintTan, 1e-30);
    // 1. farthest from the mean; then 2. farthest from the first, 3. the largest sum of squares.
    float best = -1.0;
    vec3 seedPosition = vec3(0.0), seedNormal = vec3(0.0, 0.0, 1.0);
    for (int s = 0; s < SAMPLES; ++s) {
      float score = sampleDistance2(position[s], normal[s], meanPosition, meanNormal);
      if (kind[s] == 0 && score > best) best = score, seedPosition = position[s], seedNormal = normal[s];
    }
    bool seeking = true;  // (a flag, not `break`: docs/architecture.md)
    for (int a = 0; a < MAX_AGGREGATES; ++a) {
      if (seeking) {
        // The seed just taken (a): every sample's distances to it.
        for (int s = 0; s < SAMPLES; ++s) {
          float dist = sampleDistance2(position[s], normal[s], seedPosition, seedNormal);
          if (dist < nearest[s]) nearest[s] = dist, seedOf[s] = uint(a);
          sumSquares[s] += dist * dist;
        }
        seedCount = a + 1;
        // The next seed, farther than t from every seed so far; none after the last.
        best = -1.0;
        bool found = false;
        if (a + 1 < MAX_AGGREGATES)
          for (int s = 0; s < SAMPLES; ++s) {
            float score = a == 0 ? nearest[s] : sumSquares[s];
            if (kind[s] == 0 && nearest[s] > uThreshold && score > best)
              best = score, found = true, seedPosition = position[s], seedNormal = normal[s];
          }
        seeking = found;
      }
    }
  }

  bool anyBackground = false, anyUnusable = false;
  uvec2 assignment = uvec2(0u);
  for (int s = 0; s < SAMPLES; ++s) {
    uint slice = kind[s] == 0 ? seedOf[s] : kind[s] == 1 ? uint(seedCount) : NO_SLICE;
    anyBackground = anyBackground || kind[s] == 1;
    anyUnusable = anyUnusable || kind[s] == 2;
    if (s < 10) assignment.x |= slice << uint(3 * s); else assignment.y |= slice << uint(3 * (s - 10));
  }
  int count = max(seedCount + (anyBackground ? 1 : 0), 1);
  bool allBackground = anyBackground && geometry == 0 && count == 1;
  bool onePrimitive = count == 1 && geometry == SAMPLES && normalsAgree;
  if (allBackground && !anyUnusable || onePrimitive) assignment.y |= RESOLVE_HOLDS_AGGREGATE;
  outCount = uint(count);
  outAssignment = assignment;
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
