#version 450 core
// G-buffer: location 0 the world normal, octahedral in [-1, 1]² (RG16F); location 1 albedo and a
// specular intensity (RGBA8); location 2 the world position, where the G-buffer keeps one.
#include "second/octahedral.glsl"
#include "material.glsl"
in vec3 vWorldNormal;
in vec3 vWorldPosition;
in vec2 vUv;
in vec4 vWorldTangent;
uniform vec3 uAlbedo;
uniform float uSpecular;
layout(location = 0) out vec2 outNormal;
layout(location = 1) out vec4 outAlbedoSpecular;
layout(location = 2) out vec4 outWorldPosition;
void main() {
  outNormal = octahedralEncode(mappedNormal(vWorldNormal, vWorldTangent, vUv, gl_FrontFacing));
  outAlbedoSpecular = vec4(uAlbedo * albedoAt(vUv), uSpecular * specularAt(vUv).r);
  outWorldPosition = vec4(vWorldPosition, 1.0);
}
