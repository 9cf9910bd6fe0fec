// Shared by SMAA's three passes (Jimenez et al., "SMAA: Enhanced Subpixel Morphological
// Antialiasing", Eurographics 2012). Written from the paper and the authors' reference (iryoku/smaa,
// read for the algorithm). Texture coordinates run as GL's do (y up): every "top" of the reference
// is our row below, so the whole algorithm runs on the vertically mirrored image, which it treats
// symmetrically; the S2x subsample offsets are chosen in the same mirrored frame (smaa.cpp).
uniform vec4 uMetrics;  // 1 / width, 1 / height, width, height

// SMAA_HDR_INPUT: the input is linear HDR light (S2x runs before the host's tonemap), so the edge
// thresholds see it through a perceptual stand-in for a tonemap, and blending needs no decoding.
// Otherwise the input is the tonemapped display: thresholds on its perceptual (gamma-encoded) values,
// blending in linear light, as the reference does through sRGB views (common/display_encoding.glsl: a
// display that holds linear light is encoded for the thresholds and blended as stored).
#include "common/display_encoding.glsl"
vec3 perceptual(vec3 c) {
#if SMAA_HDR_INPUT
  if (any(isnan(c)) || any(isinf(c))) return vec3(1.0);  // a broken light value is bright, not an edge-eater
  c = max(c, vec3(0.0));
  return sqrt(c / (1.0 + c));
#else
  return displayToPerceptual(c);
#endif
}
