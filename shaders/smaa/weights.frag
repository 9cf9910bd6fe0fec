#version 450 core
// SMAA pass 2: blending weights. For each edge pixel: search along the edge line both ways (two
// pixels per bilinear fetch, the search texture resolving the last step), read the crossing edges at
// both ends, and look up in the area texture how much of this pixel the revectorised silhouette
// covers on either side. Diagonal lines are searched first and win; sharp corners keep part of their
// colour (corner rounding). r, g: areas for the edge at y − 1 (g moves colour across it from below,
// r from this side); b, a: the same for the edge at x − 1.
// The plugin prepends SMAA_MAX_SEARCH_STEPS, SMAA_MAX_SEARCH_STEPS_DIAG (0: no diagonals) and
// SMAA_CORNER_ROUNDING (100: none). Lookup tables: plugin/tools/smaa_lookup_tables.cpp.
#include "smaa/smaa_common.glsl"
layout(binding = 0) uniform sampler2D uEdges;    // pass 1's edges, bilinear
layout(binding = 1) uniform sampler2D uArea;     // RG8 area texture, bilinear
layout(binding = 2) uniform usampler2D uSearch;  // R8UI search texture, fetched
// Area-texture rows per edge direction: x for edges at x − 1, y for edges at y − 1, z and w for the
// two diagonal directions. 0 for SMAA 1x; S2x passes each sample's (smaa.cpp).
uniform vec4 uSubsampleIndices;
out vec4 outWeights;

#define AREATEX_MAX_DISTANCE 16.0
#define AREATEX_MAX_DISTANCE_DIAG 20.0
#define AREATEX_PIXEL_SIZE (1.0 / vec2(160.0, 560.0))
#define AREATEX_SUBTEX_SIZE (1.0 / 7.0)
#define CORNER_ROUNDING_NORM (float(SMAA_CORNER_ROUNDING) / 100.0)

vec4 edgesAt(vec2 uv) { return textureLod(uEdges, uv, 0.0); }
#define edgesAtOffset(uv, offset) textureLodOffset(uEdges, uv, 0.0, offset)

// ---- Diagonal searches -------------------------------------------------------------------------
#if SMAA_MAX_SEARCH_STEPS_DIAG > 0
// A fetch a quarter texel right of a texel centre mixes its r with the next texel's: r reads 0.25
// or 1.0 when set, g 0.75 or 1.0; this recovers the two bits.
vec2 decodeDiagBilinear(vec2 e) {
  e.r = e.r * abs(5.0 * e.r - 5.0 * 0.75);
  return round(e);
}
vec4 decodeDiagBilinear(vec4 e) {
  e.rb = e.rb * abs(5.0 * e.rb - 5.0 * 0.75);
  return round(e);
}

vec2 searchDiag1(vec2 uv, vec2 dir, out vec2 e) {
  vec4 coord = vec4(uv, -1.0, 1.0);
  e = vec2(0.0);
  while (coord.z < float(SMAA_MAX_SEARCH_STEPS_DIAG - 1) && coord.w > 0.9) {
    coord.xyz += vec3(uMetrics.xy * dir, 1.0);
    e = edgesAt(coord.xy).rg;
    coord.w = dot(e, vec2(0.5));
  }
  return coord.zw;
}
vec2 searchDiag2(vec2 uv, vec2 dir, out vec2 e) {
  vec4 coord = vec4(uv, -1.0, 1.0);
  coord.x += 0.25 * uMetrics.x;  // both edges in one bilinear fetch (decodeDiagBilinear)
  e = vec2(0.0);
  while (coord.z < float(SMAA_MAX_SEARCH_STEPS_DIAG - 1) && coord.w > 0.9) {
    coord.xyz += vec3(uMetrics.xy * dir, 1.0);
    e = decodeDiagBilinear(edgesAt(coord.xy).rg);
    coord.w = dot(e, vec2(0.5));
  }
  return coord.zw;
}

vec2 areaDiag(vec2 dist, vec2 e, float subsample) {
  vec2 uv = AREATEX_MAX_DISTANCE_DIAG * e + dist;
  uv = AREATEX_PIXEL_SIZE * uv + 0.5 * AREATEX_PIXEL_SIZE;
  uv.x += 0.5;  // the diagonal half
  uv.y += AREATEX_SUBTEX_SIZE * subsample;
  return textureLod(uArea, uv, 0.0).rg;
}

vec2 diagonalWeights(vec2 uv, vec2 e) {
  vec2 weights = vec2(0.0);
  vec4 d;
  vec2 end;
  // The line through the pixel going −x/+y … +x/−y.
  if (e.r > 0.0) {
    d.xz = searchDiag1(uv, vec2(-1.0, 1.0), end);
    d.x += float(end.y > 0.9);
  } else {
    d.xz = vec2(0.0);
  }
  d.yw = searchDiag1(uv, vec2(1.0, -1.0), end);
  if (d.x + d.y > 2.0) {  // a line of more than three pixels
    vec4 coords = vec4(-d.x + 0.25, d.x, d.y, -d.y - 0.25) * uMetrics.xyxy + uv.xyxy;
    vec4 c;
    c.xy = edgesAtOffset(coords.xy, ivec2(-1, 0)).rg;
    c.zw = edgesAtOffset(coords.zw, ivec2(1, 0)).rg;
    c.yxwz = decodeDiagBilinear(c.xyzw);
    vec2 cc = 2.0 * c.xz + c.yw;  // crossing edges at each end, as one number
    cc = mix(cc, vec2(0.0), step(vec2(0.9), d.zw));  // no end found: no crossing edge
    weights += areaDiag(d.xy, cc, uSubsampleIndices.z);
  }
  // The line going −x/−y … +x/+y.
  d.xz = searchDiag2(uv, vec2(-1.0, -1.0), end);
  if (edgesAtOffset(uv, ivec2(1, 0)).r > 0.0) {
    d.yw = searchDiag2(uv, vec2(1.0, 1.0), end);
    d.y += float(end.y > 0.9);
  } else {
    d.yw = vec2(0.0);
  }
  if (d.x + d.y > 2.0) {
    vec4 coords = vec4(-d.x, -d.x, d.y, d.y) * uMetrics.xyxy + uv.xyxy;
    vec4 c;
    c.x = edgesAtOffset(coords.xy, ivec2(-1, 0)).g;
    c.y = edgesAtOffset(coords.xy, ivec2(0, -1)).r;
    c.zw = edgesAtOffset(coords.zw, ivec2(1, 0)).gr;
    vec2 cc = 2.0 * c.xz + c.yw;
    cc = mix(cc, vec2(0.0), step(vec2(0.9), d.zw));
    weights += areaDiag(d.xy, cc, uSubsampleIndices.w).gr;
  }
  return weights;
}
#endif

// ---- Horizontal and vertical searches ----------------------------------------------------------
// The search texture: how far (0..2 pixels) the last two-pixel step overshot the line's end, from
// the bilinear value of the four edges that step fetched (each value · 32 is an integer code).
float overshoot(vec2 e, bool towardsPlus) {
  ivec2 texel = ivec2(round(clamp(e, 0.0, 1.0) * 32.0));
  texel.x += towardsPlus ? 33 : 0;
  return float(texelFetch(uSearch, texel, 0).r);
}

// Fetches sit at (−0.25, −0.125) texels from the centre, reading four edges at once. 3.25 texels
// undo that offset, the search's bias of one and its last step; the overshoot comes off.
float searchXLeft(vec2 uv, float end) {
  vec2 e = vec2(0.0, 1.0);
  while (uv.x > end && e.g > 0.8281 && e.r == 0.0) {  // both edges of the pair set, no crossing edge
    e = edgesAt(uv).rg;
    uv.x -= 2.0 * uMetrics.x;
  }
  return uv.x + uMetrics.x * (3.25 - overshoot(e, false));
}
float searchXRight(vec2 uv, float end) {
  vec2 e = vec2(0.0, 1.0);
  while (uv.x < end && e.g > 0.8281 && e.r == 0.0) {
    e = edgesAt(uv).rg;
    uv.x += 2.0 * uMetrics.x;
  }
  return uv.x - uMetrics.x * (3.25 - overshoot(e, true));
}
float searchYDown(vec2 uv, float end) {  // towards −y
  vec2 e = vec2(1.0, 0.0);
  while (uv.y > end && e.r > 0.8281 && e.g == 0.0) {
    e = edgesAt(uv).rg;
    uv.y -= 2.0 * uMetrics.y;
  }
  return uv.y + uMetrics.y * (3.25 - overshoot(e.gr, false));
}
float searchYUp(vec2 uv, float end) {  // towards +y
  vec2 e = vec2(1.0, 0.0);
  while (uv.y < end && e.r > 0.8281 && e.g == 0.0) {
    e = edgesAt(uv).rg;
    uv.y += 2.0 * uMetrics.y;
  }
  return uv.y - uMetrics.y * (3.25 - overshoot(e.gr, true));
}

// The area for distances `dist` (square-rooted: the texture stores them quadratically) and crossing
// edges e1, e2 (bilinear reads of 0, 0.25, 0.75 or 1).
vec2 area(vec2 dist, float e1, float e2, float subsample) {
  vec2 uv = AREATEX_MAX_DISTANCE * round(4.0 * vec2(e1, e2)) + dist;
  uv = AREATEX_PIXEL_SIZE * uv + 0.5 * AREATEX_PIXEL_SIZE;
  uv.y += AREATEX_SUBTEX_SIZE * subsample;
  return textureLod(uArea, uv, 0.0).rg;
}

// ---- Corner rounding ---------------------------------------------------------------------------
void horizontalCorners(inout vec2 weights, vec2 uv, vec2 d) {
#if SMAA_CORNER_ROUNDING < 100
  vec4 coords = vec4(d.x, 0.0, d.y, 0.0) * uMetrics.xyxy + uv.xyxy;
  vec2 leftRight = step(abs(d.xy), abs(d.yx));
  vec2 rounding = (1.0 - CORNER_ROUNDING_NORM) * leftRight;
  rounding /= leftRight.x + leftRight.y;  // less for pixels in the middle of a line
  vec2 factor = vec2(1.0);
  factor.x -= rounding.x * edgesAtOffset(coords.xy, ivec2(0, 1)).r;
  factor.x -= rounding.y * edgesAtOffset(coords.zw, ivec2(1, 1)).r;
  factor.y -= rounding.x * edgesAtOffset(coords.xy, ivec2(0, -2)).r;
  factor.y -= rounding.y * edgesAtOffset(coords.zw, ivec2(1, -2)).r;
  weights *= clamp(factor, 0.0, 1.0);
#endif
}
void verticalCorners(inout vec2 weights, vec2 uv, vec2 d) {
#if SMAA_CORNER_ROUNDING < 100
  vec4 coords = vec4(0.0, d.x, 0.0, d.y) * uMetrics.xyxy + uv.xyxy;
  vec2 leftRight = step(abs(d.xy), abs(d.yx));
  vec2 rounding = (1.0 - CORNER_ROUNDING_NORM) * leftRight;
  rounding /= leftRight.x + leftRight.y;
  vec2 factor = vec2(1.0);
  factor.x -= rounding.x * edgesAtOffset(coords.xy, ivec2(1, 0)).g;
  factor.x -= rounding.y * edgesAtOffset(coords.zw, ivec2(1, 1)).g;
  factor.y -= rounding.x * edgesAtOffset(coords.xy, ivec2(-2, 0)).g;
  factor.y -= rounding.y * edgesAtOffset(coords.zw, ivec2(-2, 1)).g;
  weights *= clamp(factor, 0.0, 1.0);
#endif
}

void main() {
  vec2 uv = gl_FragCoord.xy * uMetrics.xy;
  vec2 pixel = gl_FragCoord.xy;
  vec4 offset0 = uMetrics.xyxy * vec4(-0.25, -0.125, 1.25, -0.125) + uv.xyxy;
  vec4 offset1 = uMetrics.xyxy * vec4(-0.125, -0.25, -0.125, 1.25) + uv.xyxy;
  vec4 ends = uMetrics.xxyy * vec4(-2.0, 2.0, -2.0, 2.0) * float(SMAA_MAX_SEARCH_STEPS) +
              vec4(offset0.xz, offset1.yw);
  vec4 weights = vec4(0.0);
  vec2 e = texelFetch(uEdges, ivec2(pixel), 0).rg;

  if (e.g > 0.0) {  // an edge at y − 1
#if SMAA_MAX_SEARCH_STEPS_DIAG > 0
    // Diagonals have edges on both sides, so looking for them from this one is enough; they win.
    weights.rg = diagonalWeights(uv, e);
    if (weights.r == -weights.g) {
#endif
      vec2 d;
      vec2 coords;
      coords.x = searchXLeft(offset0.xy, ends.x);
      coords.y = offset1.y;  // a quarter texel off, to tell the crossing edges apart
      d.x = coords.x;
      float e1 = edgesAt(coords).r;
      coords.x = searchXRight(offset0.zw, ends.y);
      d.y = coords.x;
      d = uMetrics.z * d - pixel.x;  // in pixels
      vec2 sqrtD = sqrt(abs(d));
      float e2 = edgesAtOffset(coords, ivec2(1, 0)).r;
      weights.rg = area(sqrtD, e1, e2, uSubsampleIndices.y);
      horizontalCorners(weights.rg, uv, d);
#if SMAA_MAX_SEARCH_STEPS_DIAG > 0
    } else {
      e.r = 0.0;  // a diagonal: no vertical processing
    }
#endif
  }

  if (e.r > 0.0) {  // an edge at x − 1
    vec2 d;
    vec2 coords;
    coords.y = searchYDown(offset1.xy, ends.z);
    coords.x = offset0.x;
    d.x = coords.y;
    float e1 = edgesAt(coords).g;
    coords.y = searchYUp(offset1.zw, ends.w);
    d.y = coords.y;
    d = uMetrics.w * d - pixel.y;
    vec2 sqrtD = sqrt(abs(d));
    float e2 = edgesAtOffset(coords, ivec2(0, 1)).g;
    weights.ba = area(sqrtD, e1, e2, uSubsampleIndices.x);
    verticalCorners(weights.ba, uv, d);
  }
  outWeights = weights;
}
