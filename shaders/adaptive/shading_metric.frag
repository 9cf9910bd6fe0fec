#version 450 core
// Holländer et al.: the shading metric, after the first sample of every pixel is lit, and the final
// sample count k = clamp(ceil(max(k_geo, k_s)), k_min, N) as the pixel's slice count.
//   r = luma range over the pixel and its 4 neighbours (luma of x / (1 + x), a display-like scale);
//   k_s = 0 if r < max(t_min, l_max · t_edge) (FXAA's thresholds), else c_s · N · r.
// Not the paper's: neighbours compared at this pixel's albedo, and k_t, the same rule (with its own
// scale c_t) on the pixel's first lit radiance scaled by its albedo's range over the window (the
// geometry metric's g, b and a): texture detail the first sample misses.
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "adaptive/shading_rule.glsl"
layout(binding = 0) uniform sampler2D uFirstLight;     // slice 0, lit by the host
layout(binding = 1) uniform sampler2D uGeometryK;
uniform float uTextureScale;
uniform int uMinSamples;
layout(location = 0) out uint outCount;

#include "common/quad_exchange.glsl"

// Inside the image: a helper fragment's too.
ivec2 clampedToImage(ivec2 pixel) { return clamp(pixel, ivec2(0), textureSize(uFirstLight, 0) - 1); }
// A pixel's first lit luma and albedo luma.
vec2 lumaAndAlbedo(ivec2 pixel) {
  ivec2 at = clampedToImage(pixel);
  return vec2(linearLuma(texelFetch(uFirstLight, at, 0).rgb), texelFetch(uGeometryK, at, 0).a);
}

// A neighbour's first lit luma as if it had this pixel's albedo luma `ownAlbedo` (both known, else 0):
// texture contrast between pixels is no shading to refine, the albedo term below sees texture inside
// the window.
float lumaAtOwnAlbedo(vec2 neighbour, float ownAlbedo) {
  float scale = ownAlbedo > 0.0 && neighbour.y > 0.0 ? clamp(ownAlbedo / neighbour.y, 1.0 / 64.0, 64.0) : 1.0;
  return toDisplay(neighbour.x * scale);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometryK, clampedToImage(pixel), 0);
  vec2 own = vec2(linearLuma(texelFetch(uFirstLight, clampedToImage(pixel), 0).rgb), geometry.a);
  float ownAlbedo = own.y;
  // Of the four neighbours two are in this pixel's quad; the other two are fetched.
  int sideX = quadPartnerSideX(), sideY = quadPartnerSideY();
  vec2 partnerX = quadPartnerX(own, sideX), partnerY = quadPartnerY(own, sideY);
  vec2 outsideX = lumaAndAlbedo(pixel - ivec2(sideX, 0)), outsideY = lumaAndAlbedo(pixel - ivec2(0, sideY));
  float l0 = lumaAtOwnAlbedo(own, ownAlbedo);
  float l1 = lumaAtOwnAlbedo(partnerX, ownAlbedo), l2 = lumaAtOwnAlbedo(outsideX, ownAlbedo);
  float l3 = lumaAtOwnAlbedo(partnerY, ownAlbedo), l4 = lumaAtOwnAlbedo(outsideY, ownAlbedo);
  float lMax = max(l0, max(max(l1, l2), max(l3, l4)));
  float kShading = shadingK(min(l0, min(min(l1, l2), min(l3, l4))), lMax);
  float firstLuma = own.x;
  float kTexture = shadingK(toDisplay(firstLuma * geometry.g), toDisplay(firstLuma * geometry.b), uTextureScale);
  float k = max(geometry.r, max(kShading, kTexture));
  int count = clamp(int(ceil(k)), max(uMinSamples, 1), SAMPLES);
  outCount = uint(count);
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
