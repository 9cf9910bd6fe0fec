// What the second host's lighting reads back per pixel: the world position rebuilt from the reversed-Z
// depth buffer and the inverse view-projection, the decoded normal, albedo and specular.
#include "second/octahedral.glsl"
layout(binding = 0) uniform sampler2D uNormal;
layout(binding = 1) uniform sampler2D uAlbedoSpecular;
layout(binding = 2) uniform sampler2D uDepth;
uniform mat4 uInverseViewProjection;
uniform vec2 uViewportSize;
uniform vec3 uCameraPosition;
uniform float uExposure;

struct Surface {
  bool background;  // depth at the far value (0, reversed-Z)
  vec3 position, normal, albedo, toEye;
  float specular;
};

Surface readSurface(ivec2 pixel) {
  Surface s;
  float depth = texelFetch(uDepth, pixel, 0).r;
  s.background = depth <= 0.0;
  vec4 clip = vec4((vec2(pixel) + 0.5) / uViewportSize * 2.0 - 1.0, depth, 1.0);  // zero-to-one depth
  vec4 world = uInverseViewProjection * clip;
  s.position = world.xyz / world.w;
  s.normal = octahedralDecode(texelFetch(uNormal, pixel, 0).xy);
  vec4 albedoSpecular = texelFetch(uAlbedoSpecular, pixel, 0);
  s.albedo = albedoSpecular.rgb;
  s.specular = albedoSpecular.a;
  s.toEye = normalize(uCameraPosition - s.position);
  return s;
}

// Lambert plus a Blinn-Phong lobe of fixed exponent.
vec3 shade(Surface s, vec3 toLight, vec3 radiance) {
  float lambert = max(dot(s.normal, toLight), 0.0);
  if (lambert <= 0.0) return vec3(0.0);
  float highlight = pow(max(dot(s.normal, normalize(toLight + s.toEye)), 0.0), 48.0);
  return radiance * (s.albedo * lambert + s.specular * highlight);
}
