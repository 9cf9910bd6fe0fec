#version 450 core
layout(location = 0) in vec3 inPosition;
uniform mat4 uVolumeToView;
uniform mat4 uProjection;
void main() { gl_Position = uProjection * uVolumeToView * vec4(inPosition, 1.0); }
