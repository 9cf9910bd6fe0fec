#version 450 core
// The second host's objects: world-space normals, one model-view-projection per draw.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform mat3 uNormalToWorld;
out vec3 vWorldNormal;
out vec3 vWorldPosition;
out vec2 vUv;
out vec4 vWorldTangent;
void main() {
  vWorldNormal = uNormalToWorld * inNormal;
  vWorldTangent = vec4(mat3(uModel) * inTangent.xyz, inTangent.w);
  vUv = inUv;
  vec4 world = uModel * vec4(inPosition, 1.0);
  vWorldPosition = world.xyz;
  gl_Position = uViewProjection * world;
}
