// `edge`'s detectors (Thibieroz): whether a pixel's samples see more than one surface, by EDGE_DETECTOR
// (one of the DETECTOR_* values the plugin injects, shared_constants.h). Included by the edge mask pass
// (detect_edges.frag) and by the resolve, which runs it on the samples it has already fetched
// (DETECTOR_VALUE(a, s): attachment a of sample s of `pixel`). The including pass declares uFootprintTan.
#ifndef DETECTOR_VALUE
#define DETECTOR_VALUE(a, s) FETCH(uAttachments[a], pixel, s)
#endif

#include "common/quad_exchange.glsl"

uniform float uDepthCloseness;  // c of the depth detector
uniform float uNormalCosine;    // cos(angle) of the normal detector

// The depth slope of the pixel's own surface along one axis, from sample 0 of its two neighbours: the
// smaller one-sided difference, since the side that crosses a silhouette has the larger one (Lauritzen's
// dFdx takes whichever side the quad pairs, and a silhouette's then hides every sample behind it). Where
// the two sides slope opposite ways the pixel is a ridge or a thin feature, and no slope is trusted.
float surfaceSlope(float before, float centre, float after) {
  float toBefore = centre - before, toAfter = after - centre;  // NaN or inf beside background
  bool beforeOk = !isnan(toBefore) && !isinf(toBefore), afterOk = !isnan(toAfter) && !isinf(toAfter);
  if (beforeOk && afterOk) return toBefore * toAfter > 0.0 ? min(abs(toBefore), abs(toAfter)) : 0.0;
  return beforeOk ? abs(toBefore) : afterOk ? abs(toAfter) : 0.0;
}

// Whether every sample lies on sample 0's plane, with its normal: depth within the surface's slope across
// one pixel (sample offsets are under a pixel), normals within 8 degrees. Samples of one surface shaded per
// sample (a cut-out's texture read at each sample, interpolated normals) pass; a second surface does not.
// `quad`: sample 0's distance here and at the pixel's quad partners (planeInputs).
struct PlaneInputs {
  float d0;
  vec2 partnerD0;  // across x, across y
  ivec2 side;      // where each partner lies: +1 after this pixel, -1 before
};
bool samplesShareOnePlane(ivec2 pixel, PlaneInputs quad) {
  float d0 = quad.d0;
  vec3 n0 = sampleNormal(pixel, 0);
  ivec2 last = gbufferPixels() - 1;
  float slope = 0.0;
  if (!isinf(d0)) {
    // Per axis the neighbour beyond the quad is fetched; the one inside it came with the quad.
    slope = surfaceSlope(sampleDistance(ivec2(clamp(pixel.x - quad.side.x, 0, last.x), pixel.y), 0), d0,
                         quad.partnerD0.x) +
            surfaceSlope(sampleDistance(ivec2(pixel.x, clamp(pixel.y - quad.side.y, 0, last.y)), 0), d0,
                         quad.partnerD0.y);
  }
  // No jumps in the loop (see resolve.glsl): it unrolls, and the resolve's arrays stay in registers.
  bool onePlane = true;
  for (int s = 1; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    if (isinf(d) || isinf(d0))
      onePlane = onePlane && isinf(d) == isinf(d0);  // background beside background only
    else
      onePlane = onePlane && !(abs(d - d0) > slope + 1e-5 * d0 || dot(sampleNormal(pixel, s), n0) < 0.99);
  }
  return onePlane;
}

// The plane test's inputs, taken in uniform control flow (the quad exchange needs every fragment of the
// quad, helpers included): two of its four neighbour fetches come from the quad instead.
PlaneInputs planeInputs(ivec2 pixel) {
  PlaneInputs quad;
  quad.d0 = sampleDistance(pixel, 0);
  quad.side = ivec2(quadPartnerSideX(), quadPartnerSideY());
  quad.partnerD0 = vec2(quadPartnerX(vec2(quad.d0), quad.side.x).x, quadPartnerY(vec2(quad.d0), quad.side.y).x);
  return quad;
}

// `pixel` inside the G-buffer: a helper fragment beyond its last column or row passes the last one's.
bool isEdge(ivec2 pixel) {
#if EDGE_DETECTOR == DETECTOR_EVERY_PIXEL
  return true;
#elif EDGE_DETECTOR == DETECTOR_PLANE
  return !samplesShareOnePlane(pixel, planeInputs(pixel));
#elif EDGE_DETECTOR == DETECTOR_COVERAGE
  // A model shader run once per pixel and primitive writes the same outputs into every sample the
  // primitive covers, so bit-identical samples are one surface. Different ones are a second primitive,
  // or one surface shaded per sample (cut-out draws, `sample_shading`, a driver's 16x mode): the plane
  // test tells them apart. It runs once, after the loops (inside them it would be inlined at every
  // unrolled exit and run under each one's lanes).
  PlaneInputs quad = planeInputs(pixel);
  bool differs = false;
  for (int s = 1; s < SAMPLES; ++s)
#define DIFFERS_FROM_FIRST(a) differs = differs || DETECTOR_VALUE(a, s) != DETECTOR_VALUE(a, 0);
    FOR_EACH_ATTACHMENT(DIFFERS_FROM_FIRST)
  return differs && !samplesShareOnePlane(pixel, quad);
#else
  float d0 = sampleDistance(pixel, 0);
  vec3 n0 = sampleNormal(pixel, 0);
  bool edge = false;  // (no jumps in the loop: see samplesShareOnePlane)
  for (int s = 1; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    if (isinf(d) || isinf(d0)) {
      edge = edge || isinf(d) != isinf(d0);  // geometry beside background; background beside background is none
    } else {
#if EDGE_DETECTOR == DETECTOR_DEPTH
      edge = edge || abs(d - d0) > min(d, d0) * uFootprintTan * uDepthCloseness;
#elif EDGE_DETECTOR == DETECTOR_NORMAL
      edge = edge || dot(normalize(sampleNormal(pixel, s)), normalize(n0)) < uNormalCosine;
#elif EDGE_DETECTOR == DETECTOR_MATERIAL
      // The material channels the layout has: albedo, specular, and gloss beside an xyz normal.
      bool differs = false;
#if ALBEDO_ATTACHMENT >= 0
      differs = differs ||
                any(greaterThan(abs(DETECTOR_VALUE(ALBEDO_ATTACHMENT, s) - DETECTOR_VALUE(ALBEDO_ATTACHMENT, 0)),
                                vec4(1.0 / 512.0)));
#endif
#if SPECULAR_ATTACHMENT >= 0
      differs = differs ||
                any(greaterThan(abs(DETECTOR_VALUE(SPECULAR_ATTACHMENT, s) - DETECTOR_VALUE(SPECULAR_ATTACHMENT, 0)),
                                vec4(1.0 / 512.0)));
#endif
#if NORMAL_ATTACHMENT >= 0 && NORMAL_ENCODING == NORMAL_XYZ
      differs = differs || abs(DETECTOR_VALUE(NORMAL_ATTACHMENT, s).w - DETECTOR_VALUE(NORMAL_ATTACHMENT, 0).w) > 1.0 / 512.0;
#endif
#if NORMAL_ATTACHMENT >= 0 && NORMAL_ENCODING == NORMAL_SPHEREMAP  // zw: the host's material (STK: roughness, metallic)
      differs = differs || any(greaterThan(abs(DETECTOR_VALUE(NORMAL_ATTACHMENT, s).zw -
                                               DETECTOR_VALUE(NORMAL_ATTACHMENT, 0).zw),
                                           vec2(1.0 / 512.0)));
#endif
      edge = edge || differs;
#endif
    }
  }
  return edge;
#endif
}
