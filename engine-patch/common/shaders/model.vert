#version 450 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;
uniform mat4 uCurrentClip, uPreviousClip;  // model to clip, this frame and the previous, without jitter
out vec3 vViewPosition;
out vec4 vCurrentClip, vPreviousClip;
out vec3 vNormal;
out vec2 vUv;
out vec4 vTangent;
void main() {
  vec4 viewPosition = uModelView * vec4(inPosition, 1.0);
  vViewPosition = viewPosition.xyz;
  vNormal = uNormalMatrix * inNormal;
  vUv = inUv;
  vTangent = vec4(mat3(uModelView) * inTangent.xyz, inTangent.w);
  gl_Position = uProjection * viewPosition;
  vCurrentClip = uCurrentClip * vec4(inPosition, 1.0);
  vPreviousClip = uPreviousClip * vec4(inPosition, 1.0);
}
