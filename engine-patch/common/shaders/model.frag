#version 450 core
#include "depth_codec.glsl"
#include "gbuffer_outputs.glsl"
#include "material.glsl"
in vec3 vViewPosition;
in vec3 vNormal;
in vec2 vUv;
in vec4 vTangent;
in vec4 vCurrentClip, vPreviousClip;
uniform vec2 uViewportPixels;
uniform vec3 uAlbedo;
uniform vec3 uSpecular;
uniform float uGloss;
uniform vec3 uEmissive;
uniform float uNear;
uniform float uFar;
void main() {
  float d = -vViewPosition.z;
  vec3 n = mappedNormal(vNormal, vTangent, vUv, gl_FrontFacing);
  vec4 specular = specularAt(vUv);
  outColor = vec4(uAlbedo * albedoAt(vUv), 1.0);
  // x and y divided by depth: raw view-space x reaches 1e6 m, past FP16's range.
  outPosition = vec4(vViewPosition.xy / d, encodeDepth(d), 1.0);
  outNormal = vec4(n, uGloss * specular.a);
  outSpecular = vec4(uSpecular * specular.rgb, 1.0);
  outEmissive = vec4(uEmissive * emissiveAt(vUv), 1.0);
  outVelocity = vec4((vCurrentClip.xy / vCurrentClip.w - vPreviousClip.xy / vPreviousClip.w) * 0.5 * uViewportPixels,
                     0.0, 0.0);
#ifdef LOGARITHMIC_DEPTH
  // Logarithmic depth: D24 keeps ~1e-6 relative precision from the near plane to 1e6 m. (It costs
  // early depth tests, and every sample of a primitive gets the pixel's depth.)
  gl_FragDepth = log2(max(d, uNear) / uNear) / log2(uFar / uNear);
#endif
}
