#version 450 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;
out vec3 vViewPosition;
out vec3 vNormal;
void main() {
  vec4 viewPosition = uModelView * vec4(inPosition, 1.0);
  vViewPosition = viewPosition.xyz;
  vNormal = uNormalMatrix * inNormal;
  gl_Position = uProjection * viewPosition;
}
