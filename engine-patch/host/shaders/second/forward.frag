#version 450 core
// The forward pass after lighting: emissive objects, depth-tested against the lit scene.
in vec3 vWorldNormal;
uniform vec3 uEmissive;
uniform float uExposure;
out vec4 outColour;
void main() { outColour = vec4(uEmissive * uExposure, 1.0); }
