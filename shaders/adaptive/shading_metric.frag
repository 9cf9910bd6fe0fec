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

// A neighbour's first lit luma as if it had this pixel's albedo luma `ownAlbedo` (both known, else 0):
// texture contrast between pixels is no shading to refine, the albedo term below sees texture inside
// the window.
float luma(ivec2 pixel, float ownAlbedo) {
  ivec2 at = clamp(pixel, ivec2(0), textureSize(uFirstLight, 0) - 1);
  float albedo = texelFetch(uGeometryK, at, 0).a;
  float scale = ownAlbedo > 0.0 && albedo > 0.0 ? clamp(ownAlbedo / albedo, 1.0 / 64.0, 64.0) : 1.0;
  return toDisplay(linearLuma(texelFetch(uFirstLight, at, 0).rgb) * scale);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometryK, pixel, 0);
  float ownAlbedo = geometry.a;
  float l0 = luma(pixel, ownAlbedo), lN = luma(pixel + ivec2(0, 1), ownAlbedo);
  float lS = luma(pixel - ivec2(0, 1), ownAlbedo), lE = luma(pixel + ivec2(1, 0), ownAlbedo);
  float lW = luma(pixel - ivec2(1, 0), ownAlbedo);
  float lMax = max(l0, max(max(lN, lS), max(lE, lW)));
  float kShading = shadingK(min(l0, min(min(lN, lS), min(lE, lW))), lMax);
  float firstLuma = linearLuma(texelFetch(uFirstLight, pixel, 0).rgb);
  float kTexture = shadingK(toDisplay(firstLuma * geometry.g), toDisplay(firstLuma * geometry.b), uTextureScale);
  float k = max(geometry.r, max(kShading, kTexture));
  int count = clamp(int(ceil(k)), max(uMinSamples, 1), SAMPLES);
  outCount = uint(count);
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
