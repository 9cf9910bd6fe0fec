#version 450 core
// The slices' sum, accumulated at half-float precision, written once into a host light target of 8 bits
// per channel (an sRGB display lit directly): compositing each weighted slice into it would round
// every slice's share apart.
layout(binding = 0) uniform sampler2D uAccumulated;
out vec4 outLight;
void main() { outLight = texelFetch(uAccumulated, ivec2(gl_FragCoord.xy), 0); }
