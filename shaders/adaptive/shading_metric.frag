#version 450 core
// Holländer et al.: the shading metric, after the first sample of every pixel is lit, and the final
// sample count k = clamp(ceil(max(k_geo, k_s)), k_min, N) as the pixel's slice count.
//   r = luma range over the pixel and its 4 neighbours (luma of x / (1 + x), a display-like scale);
//   k_s = 0 if r < max(t_min, l_max · t_edge) (FXAA's thresholds), else c_s · N · r.
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "adaptive/shading_rule.glsl"
layout(binding = 0) uniform sampler2D uFirstLight;     // slice 0, lit by the host
layout(binding = 2) uniform sampler2D uGeometryK;
uniform int uMinSamples;
layout(location = 0) out uint outCount;

float luma(ivec2 pixel) {
  ivec2 size = textureSize(uFirstLight, 0);
  return displayLuma(texelFetch(uFirstLight, clamp(pixel, ivec2(0), size - 1), 0).rgb);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float l0 = luma(pixel), lN = luma(pixel + ivec2(0, 1)), lS = luma(pixel - ivec2(0, 1));
  float lE = luma(pixel + ivec2(1, 0)), lW = luma(pixel - ivec2(1, 0));
  float lMax = max(l0, max(max(lN, lS), max(lE, lW)));
  float kShading = shadingK(min(l0, min(min(lN, lS), min(lE, lW))), lMax);
  float k = max(texelFetch(uGeometryK, pixel, 0).r, kShading);
  int count = clamp(int(ceil(k)), max(uMinSamples, 1), SAMPLES);
  outCount = uint(count);
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
