#version 450 core
// Holländer et al., "Adaptive Supersampling for Deferred Anti-Aliasing" (JCGT 2013): the geometry
// metric, from the G-buffer alone, before any lighting.
//   k_d = c_d · variance of the samples' depths, measured in pixel footprints at the mean depth
//         (d / (d̄ · tan(hfov / width))): scale-invariant, so a ship at 10 km and one at 10 m behave alike;
//   k_n = c_n · sqrt(1 − min_i |n̄ · n_i|), the opening of the pixel's normal cone;
// geometry beside background refines fully; background alone needs one sample, unless its stored
// radiance varies over the window.
// Not the paper's: k_e, the shading metric's rule applied to the emissive attachment across the
// pixel's own samples. Emission is radiance the G-buffer already holds, so its sub-pixel detail (stars
// in a supersampled sky, glow-map lines) is shading the first lit sample usually misses.
#include "common/gbuffer.glsl"
#include "adaptive/shading_rule.glsl"
uniform float uFootprintTan;
uniform float uDepthScale;
uniform float uNormalScale;
layout(location = 0) out float outGeometryK;

float emissiveK(ivec2 pixel) {
#if EMISSIVE_ATTACHMENT >= 0
  float lMin = 1.0, lMax = 0.0;
  for (int s = 0; s < SAMPLES; ++s) {
    float l = displayLuma(FETCH(uAttachments[EMISSIVE_ATTACHMENT], pixel, s).rgb);
    lMin = min(lMin, l);
    lMax = max(lMax, l);
  }
  return shadingK(lMin, lMax);
#else
  return 0.0;
#endif
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float kEmissive = emissiveK(pixel);
  int background = 0;
  float sum = 0.0;
  vec3 normalSum = vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    if (isinf(d) || !sampleIsFinite(pixel, s)) { ++background; continue; }
    sum += d;
#if NORMAL_ATTACHMENT >= 0
    vec3 n = sampleNormal(pixel, s);
    normalSum += dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
#endif
  }
  if (background == SAMPLES) { outGeometryK = min(kEmissive, float(SAMPLES)); return; }
  if (background > 0) { outGeometryK = float(SAMPLES); return; }
  float mean = sum / float(SAMPLES);
  float footprint = mean * uFootprintTan;
  float sumSquares = 0.0, sumFootprints = 0.0;
  float minCosine = 1.0;
  vec3 meanNormal = dot(normalSum, normalSum) > 0.0 ? normalize(normalSum) : vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    float u = (sampleDistance(pixel, s) - mean) / footprint;  // centred first: no cancellation
    sumFootprints += u;
    sumSquares += u * u;
#if NORMAL_ATTACHMENT >= 0
    vec3 n = sampleNormal(pixel, s);
    minCosine = min(minCosine, dot(n, n) > 0.0 ? abs(dot(meanNormal, normalize(n))) : 0.0);
#endif
  }
  float variance = max(sumSquares / float(SAMPLES) - pow(sumFootprints / float(SAMPLES), 2.0), 0.0);
  float kDepth = uDepthScale * variance;
  float kNormal = uNormalScale * sqrt(max(1.0 - minCosine, 0.0));
  float k = max(max(kDepth, kNormal), kEmissive);
  outGeometryK = isnan(k) ? float(SAMPLES) : min(k, float(SAMPLES));
}
