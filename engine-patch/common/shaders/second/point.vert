#version 450 core
// A light's bounding sphere, drawn for its back faces (no depth test: lit wherever it covers).
layout(location = 0) in vec3 inPosition;
uniform mat4 uViewProjection;
uniform vec3 uCentre;
uniform float uBoundRadius;
void main() { gl_Position = uViewProjection * vec4(uCentre + inPosition * uBoundRadius, 1.0); }
