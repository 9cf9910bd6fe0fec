#version 450 core
// G-buffer: location 0 the world normal, octahedral in [-1, 1]² (RG16F); location 1 albedo and a
// specular intensity (RGBA8).
#include "second/octahedral.glsl"
in vec3 vWorldNormal;
uniform vec3 uAlbedo;
uniform float uSpecular;
layout(location = 0) out vec2 outNormal;
layout(location = 1) out vec4 outAlbedoSpecular;
void main() {
  vec3 n = normalize(gl_FrontFacing ? vWorldNormal : -vWorldNormal);
  outNormal = octahedralEncode(n);
  outAlbedoSpecular = vec4(uAlbedo, uSpecular);
}
