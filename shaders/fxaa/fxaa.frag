#version 450 core
// FXAA 3.11, quality variant (Lottes 2009/2011), written from the algorithm's description:
// 1. local contrast test on luma (N, S, E, W); low-contrast pixels pass through;
// 2. edge direction from the 3×3 second derivatives;
// 3. search both ways along the edge until the luma gradient changes (FXAA_SEARCH_STEPS steps);
// 4. blend across the edge by the pixel's distance to the nearer edge end, or by the sub-pixel
//    aliasing estimate, whichever is larger.
// Input: a copy of the tonemapped display target, bilinear sampler. Luma, which every threshold reads,
// is perceptual: a display that holds linear light is encoded for it (common/display_encoding.glsl);
// the blend mixes the values as stored. The plugin prepends FXAA_SEARCH_STEPS, DISPLAY_HOLDS_LINEAR and
// FXAA_MARK_EDGES.
//
// Two draws (as SMAA's integration step 9 does for its searches): FXAA_MARK_EDGES 1 runs step 1 on every
// pixel and keeps, in a stencil, those that pass it; FXAA_MARK_EDGES 0 runs steps 2-4 on those alone and
// writes them into the display in place. A pixel below the contrast threshold is not written at all.
// One draw with an early return cost every pixel the search: llvmpipe runs both sides of a branch under a
// mask.
#include "common/display_encoding.glsl"
layout(binding = 0) uniform sampler2D uInput;
uniform vec2 uTexelSize;          // 1 / size
uniform float uEdgeThreshold;     // relative contrast needed (0.063 .. 0.333)
uniform float uEdgeThresholdMin;  // absolute contrast floor for dark areas
uniform float uSubpixel;          // sub-pixel aliasing removal, 0 .. 1
out vec4 outColour;

float lumaOf(vec3 stored) { return dot(displayToPerceptual(stored), vec3(0.299, 0.587, 0.114)); }
float luma(vec2 uv) { return lumaOf(textureLod(uInput, uv, 0.0).rgb); }
// The 3×3 neighbourhood lies on texel centres, where the bilinear filter returns the texel itself: it is
// fetched unfiltered, clamped to the edge as the sampler is (the same image; on llvmpipe the pass 2.3-2.6
// → 1.8-1.9 ms on the demo frame).
float lumaAt(ivec2 offset) {
  ivec2 texel = clamp(ivec2(gl_FragCoord.xy) + offset, ivec2(0), textureSize(uInput, 0) - 1);
  return lumaOf(texelFetch(uInput, texel, 0).rgb);
}

// Search step lengths (in texels) of the quality presets: short steps first, then longer strides.
float searchStep(int i) {
  const float steps[12] = float[12](1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0, 8.0);
  return FXAA_SEARCH_STEPS <= 3 ? (i == 0 ? 1.0 : (i == 1 ? 1.5 : 4.0)) : steps[i];
}

void main() {
  vec2 uv = gl_FragCoord.xy * uTexelSize;
  vec4 centre = texelFetch(uInput, ivec2(gl_FragCoord.xy), 0);
  float lumaM = lumaOf(centre.rgb);
  float lumaN = lumaAt(ivec2(0, 1)), lumaS = lumaAt(ivec2(0, -1));
  float lumaE = lumaAt(ivec2(1, 0)), lumaW = lumaAt(ivec2(-1, 0));
  float lumaMax = max(lumaM, max(max(lumaN, lumaS), max(lumaE, lumaW)));
  float lumaMin = min(lumaM, min(min(lumaN, lumaS), min(lumaE, lumaW)));
  float range = lumaMax - lumaMin;
#if FXAA_MARK_EDGES
  if (range < max(uEdgeThresholdMin, lumaMax * uEdgeThreshold)) discard;  // NaN: filtered, as it always was
#else
  float lumaNW = lumaAt(ivec2(-1, 1)), lumaNE = lumaAt(ivec2(1, 1));
  float lumaSW = lumaAt(ivec2(-1, -1)), lumaSE = lumaAt(ivec2(1, -1));

  // Sub-pixel aliasing: how far the centre stands out of its 3×3 low-pass.
  float lowPass = (2.0 * (lumaN + lumaS + lumaE + lumaW) + lumaNW + lumaNE + lumaSW + lumaSE) / 12.0;
  float subpixel = smoothstep(0.0, 1.0, clamp(abs(lowPass - lumaM) / range, 0.0, 1.0));
  float subpixelBlend = subpixel * subpixel * uSubpixel;

  float edgeVertical = abs(0.25 * lumaNW - 0.5 * lumaN + 0.25 * lumaNE) + abs(0.5 * lumaW - lumaM + 0.5 * lumaE) +
                       abs(0.25 * lumaSW - 0.5 * lumaS + 0.25 * lumaSE);
  float edgeHorizontal = abs(0.25 * lumaNW - 0.5 * lumaW + 0.25 * lumaSW) + abs(0.5 * lumaN - lumaM + 0.5 * lumaS) +
                         abs(0.25 * lumaNE - 0.5 * lumaE + 0.25 * lumaSE);
  bool horizontal = edgeHorizontal >= edgeVertical;  // the edge runs along x: blend in y

  float luma1 = horizontal ? lumaS : lumaW;  // the two neighbours across the edge
  float luma2 = horizontal ? lumaN : lumaE;
  float gradient1 = abs(luma1 - lumaM), gradient2 = abs(luma2 - lumaM);
  bool towards1 = gradient1 >= gradient2;
  float stepAcross = horizontal ? uTexelSize.y : uTexelSize.x;
  if (towards1) stepAcross = -stepAcross;
  float localAverage = 0.5 * ((towards1 ? luma1 : luma2) + lumaM);
  float gradientScaled = 0.25 * max(gradient1, gradient2);

  // Walk along the edge, half a texel towards the steeper side.
  vec2 edgeUv = uv;
  if (horizontal) edgeUv.y += 0.5 * stepAcross; else edgeUv.x += 0.5 * stepAcross;
  vec2 along = horizontal ? vec2(uTexelSize.x, 0.0) : vec2(0.0, uTexelSize.y);
  vec2 uvN = edgeUv - along, uvP = edgeUv + along;
  float endN = luma(uvN) - localAverage, endP = luma(uvP) - localAverage;
  bool doneN = abs(endN) >= gradientScaled, doneP = abs(endP) >= gradientScaled;
  for (int i = 1; i < FXAA_SEARCH_STEPS && !(doneN && doneP); ++i) {
    if (!doneN) {
      uvN -= along * searchStep(i);
      endN = luma(uvN) - localAverage;
      doneN = abs(endN) >= gradientScaled;
    }
    if (!doneP) {
      uvP += along * searchStep(i);
      endP = luma(uvP) - localAverage;
      doneP = abs(endP) >= gradientScaled;
    }
  }
  float distanceN = horizontal ? uv.x - uvN.x : uv.y - uvN.y;
  float distanceP = horizontal ? uvP.x - uv.x : uvP.y - uv.y;
  bool nearerN = distanceN < distanceP;
  float endLuma = nearerN ? endN : endP;
  // Only blend when the nearer end's luma change agrees with the centre's side of the edge.
  bool centreBelow = lumaM - localAverage < 0.0;
  bool goodSpan = (endLuma < 0.0) != centreBelow;
  float offset = goodSpan ? 0.5 - min(distanceN, distanceP) / (distanceN + distanceP) : 0.0;
  offset = max(offset, subpixelBlend);
  vec2 finalUv = uv;
  if (horizontal) finalUv.y += offset * stepAcross; else finalUv.x += offset * stepAcross;
  outColour = vec4(textureLod(uInput, finalUv, 0.0).rgb, centre.a);
#endif
}
