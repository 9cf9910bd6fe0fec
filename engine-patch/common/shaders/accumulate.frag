#version 450 core
// Ground truth: adds one supersample's radiance (linear, pre-tonemap) and its display luminance
// statistics (for the edge mask) into float targets with additive blending. DISPLAY_CLAMP: the host's
// display is its radiance clamped to [0, 1] and sRGB-encoded (the second host), else FSO's tonemap.
#include "tonemap_common.glsl"
layout(binding = 0) uniform sampler2D uHdr;
uniform float uWeight;
uniform float uExposure;
layout(location = 0) out vec4 outRadiance;
layout(location = 1) out vec4 outLumaMoments;
void main() {
  vec3 hdr = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb;
#ifdef DISPLAY_CLAMP
  vec3 display = linearToSrgb(clamp(hdr, 0.0, 1.0));
#else
  vec3 display = displayColour(hdr, uExposure);
#endif
  float luma = dot(display, vec3(0.2126, 0.7152, 0.0722));
  outRadiance = vec4(hdr * uWeight, uWeight);
  outLumaMoments = vec4(luma * uWeight, luma * luma * uWeight, 0.0, 0.0);
}
