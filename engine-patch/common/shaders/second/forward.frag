#version 450 core
// The forward pass after lighting: emissive objects, and glow maps, depth-tested against the lit scene.
#include "material.glsl"
in vec2 vUv;
uniform vec3 uEmissive;
uniform float uExposure;
out vec4 outColour;
void main() { outColour = vec4(uEmissive * emissiveAt(vUv) * uExposure, 1.0); }
