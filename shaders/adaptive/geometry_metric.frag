#version 450 core
// Holländer et al., "Adaptive Supersampling for Deferred Anti-Aliasing" (JCGT 2013): the geometry
// metric, from the G-buffer alone, before any lighting.
//   k_d = c_d · variance of the samples' depths, measured in pixel footprints at the mean depth
//         (d / (d̄ · tan(hfov / width))): scale-invariant, so a ship at 10 km and one at 10 m behave alike;
//         not the paper's: or around the plane the neighbouring pixels continue, whichever is smaller,
//         so a surface seen at a grazing angle (a deck, terrain) is one surface, not a spread to refine;
//   k_n = c_n · sqrt(1 − min_i |n̄ · n_i|), the opening of the pixel's normal cone;
// geometry beside background refines fully; background alone needs one sample, unless its stored
// radiance varies over the window.
// Not the paper's: k_e, the shading metric's rule applied to the emissive attachment across the
// pixel's own samples. Emission is radiance the G-buffer already holds, so its sub-pixel detail (stars
// in a supersampled sky, glow-map lines) is shading the first lit sample usually misses.
// Also not the paper's: the range of the albedo's luma over the pixel's own samples relative to the
// first sample's (outputs g and b), and the first sample's albedo luma (a; 0 where unknown). Lit
// radiance is roughly albedo times irradiance: the shading metric scales the first lit sample by the
// ratios to see texture detail inside the window, and compares neighbours at this pixel's albedo so
// that texture contrast between pixels is not mistaken for shading inside one.
#include "common/gbuffer.glsl"
#include "adaptive/shading_rule.glsl"
uniform float uFootprintTan;
uniform float uDepthScale;
uniform float uNormalScale;
uniform int uFirstSample;                // the sample the first slice lights
uniform vec2 uSampleOffsets[SAMPLES];    // positions within the pixel less their mean, in pixels
uniform vec2 uImageSize;                  // in pixels
layout(location = 0) out vec4 outGeometryK;  // r: k_geo; g, b: albedo luma range / a; a: first albedo luma

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

vec3 albedoRange(ivec2 pixel) {
#if ALBEDO_ATTACHMENT >= 0
  float first = linearLuma(FETCH(uAttachments[ALBEDO_ATTACHMENT], pixel, uFirstSample).rgb);
  float lMin = 1.0 / 0.0, lMax = 0.0;
  for (int s = 0; s < SAMPLES; ++s) {
    float l = linearLuma(FETCH(uAttachments[ALBEDO_ATTACHMENT], pixel, s).rgb);
    lMin = min(lMin, l);
    lMax = max(lMax, l);
  }
  // Called on finite samples only. A black first sample says nothing of its irradiance: one 8-bit step.
  // Below 1/64 the albedo hardly carries the radiance (specular, emission): unknown to the neighbours.
  vec2 ratios = min(vec2(lMin, lMax) / max(first, 1.0 / 255.0), vec2(64.0));
  return vec3(ratios, first >= 1.0 / 64.0 ? first : 0.0);
#else
  return vec3(1.0, 1.0, 0.0);
#endif
}

// A pixel's mean inverse depth relative to `mean` (a depth in metres); false where the pixel is off the
// image or shows background.
bool relativeInverseDepth(ivec2 pixel, float mean, out float level) {
  level = 0.0;
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(vec2(pixel), uImageSize))) return false;
  for (int s = 0; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    if (isinf(d)) return false;
    level += mean / d;
  }
  level /= float(SAMPLES);
  return true;
}

// Per axis the gentler of the two one-sided slopes (0 where neither neighbour is a surface).
float gentlerSlope(ivec2 pixel, ivec2 axis, float mean, float level) {
  float forward, backward;
  bool hasForward = relativeInverseDepth(pixel + axis, mean, forward);
  bool hasBackward = relativeInverseDepth(pixel - axis, mean, backward);
  float ahead = forward - level, behind = level - backward;
  if (hasForward && hasBackward) return abs(ahead) < abs(behind) ? ahead : behind;
  return hasForward ? ahead : hasBackward ? behind : 0.0;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float kEmissive = emissiveK(pixel);
  int background = 0;
  float sum = 0.0;
  float distances[SAMPLES];  // fetched once: the loops below read each sample again
  vec3 normalSum = vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    float d = distances[s] = sampleDistance(pixel, s);
    if (isinf(d) || !sampleIsFinite(pixel, s)) {  // an `if`, not `continue` (docs/architecture.md)
      ++background;
    } else {
      sum += d;
#if NORMAL_ATTACHMENT >= 0
      vec3 n = sampleNormal(pixel, s);
      normalSum += dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
#endif
    }
  }
  if (background == SAMPLES) { outGeometryK = vec4(min(kEmissive, float(SAMPLES)), 1.0, 1.0, 0.0); return; }
  if (background > 0) { outGeometryK = vec4(float(SAMPLES), 1.0, 1.0, 0.0); return; }
  float mean = sum / float(SAMPLES);
  // The plane the neighbours continue, in inverse depth relative to this pixel's mean (linear in screen
  // position for any plane, ≈ 1 here): per axis the gentler of the two one-sided slopes, so a step just
  // beyond a pixel that lies wholly on one surface does not count as its own.
  float level = 0.0;
  for (int s = 0; s < SAMPLES; ++s) level += mean / distances[s];
  level /= float(SAMPLES);
  vec2 slope = vec2(gentlerSlope(pixel, ivec2(1, 0), mean, level), gentlerSlope(pixel, ivec2(0, 1), mean, level));
  // Spread about the mean (the paper's) and about that plane: the smaller counts, since depth taken from
  // a colour attachment is one value per primitive in a multisampled pixel and flat where the plane is not.
  vec2 sumSquares = vec2(0.0), sumFootprints = vec2(0.0);
  float minCosine = 1.0;
  vec3 meanNormal = dot(normalSum, normalSum) > 0.0 ? normalize(normalSum) : vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    // In pixel footprints: Δd ≈ −d̄ · Δ(d̄/d) near the mean. Centred first: no cancellation at 1e6 m.
    float offMean = mean / distances[s] - level;
    vec2 u = vec2(offMean, offMean - dot(slope, uSampleOffsets[s])) / uFootprintTan;
    sumFootprints += u;
    sumSquares += u * u;
#if NORMAL_ATTACHMENT >= 0
    vec3 n = sampleNormal(pixel, s);
    minCosine = min(minCosine, dot(n, n) > 0.0 ? abs(dot(meanNormal, normalize(n))) : 0.0);
#endif
  }
  vec2 spreads = max(sumSquares / float(SAMPLES) - sumFootprints * sumFootprints / float(SAMPLES * SAMPLES), 0.0);
  float variance = min(spreads.x, spreads.y);
  float kDepth = uDepthScale * variance;
  float kNormal = uNormalScale * sqrt(max(1.0 - minCosine, 0.0));
  float k = max(max(kDepth, kNormal), kEmissive);
  outGeometryK = vec4(isnan(k) ? float(SAMPLES) : min(k, float(SAMPLES)), albedoRange(pixel));
}
