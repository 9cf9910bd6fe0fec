// Reads the single-sample G-buffer and evaluates one light; shared by every lighting pass.
#include "depth_codec.glsl"
layout(binding = 0) uniform sampler2D uColor;
layout(binding = 1) uniform sampler2D uPosition;
layout(binding = 2) uniform sampler2D uNormal;
layout(binding = 3) uniform sampler2D uSpecular;
layout(binding = 4) uniform sampler2D uEmissive;
uniform int uShadingModel;  // 0 Blinn-Phong, 1 GGX

struct Surface {
  vec3 position;  // view space, metres
  vec3 normal;
  vec3 albedo;
  vec3 specular;
  float gloss;
  bool background;
};

Surface readSurface(ivec2 pixel) {
  Surface s;
  vec4 p = texelFetch(uPosition, pixel, 0);
  s.background = isBackgroundDepth(p.z);
  float d = decodeDepth(p.z);
  s.position = vec3(p.xy * d, -d);
  vec4 n = texelFetch(uNormal, pixel, 0);
  s.normal = dot(n.xyz, n.xyz) > 0.0 ? normalize(n.xyz) : vec3(0.0, 0.0, 1.0);  // a zero normal must not light NaN
  s.gloss = n.w;
  s.albedo = texelFetch(uColor, pixel, 0).rgb;
  s.specular = texelFetch(uSpecular, pixel, 0).rgb;
  return s;
}

const float kPi = 3.14159265;

// Radiance reflected towards the eye from a light of `radiance` arriving from direction L.
vec3 shade(Surface s, vec3 L, vec3 radiance) {
  vec3 N = s.normal;
  vec3 V = normalize(-s.position);
  float nl = dot(N, L);
  if (nl <= 0.0) return vec3(0.0);
  vec3 H = normalize(L + V);
  float nh = max(dot(N, H), 0.0);
  if (uShadingModel == 0) {
    float exponent = exp2(s.gloss * 10.0 + 1.0);
    vec3 specular = s.specular * pow(nh, exponent) * (exponent + 8.0) / 8.0;
    return (s.albedo + specular) * nl * radiance;
  }
  float roughness = max(1.0 - s.gloss, 0.03);
  float a2 = roughness * roughness * roughness * roughness;
  float denom = nh * nh * (a2 - 1.0) + 1.0;
  float D = a2 / (kPi * denom * denom);
  float nv = max(dot(N, V), 1e-4);
  vec3 F = s.specular + (1.0 - s.specular) * pow(1.0 - max(dot(V, H), 0.0), 5.0);
  float k = roughness * roughness * 0.5;
  float G = (nl / (nl * (1.0 - k) + k)) * (nv / (nv * (1.0 - k) + k));
  vec3 specular = D * F * G / (4.0 * nl * nv);
  return (s.albedo * (1.0 - F) + specular * kPi) * nl * radiance;
}
