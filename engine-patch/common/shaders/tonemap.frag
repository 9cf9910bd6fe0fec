#version 450 core
#include "tonemap_common.glsl"
layout(binding = 0) uniform sampler2D uHdr;
uniform float uExposure;
out vec4 outColour;
void main() { outColour = vec4(displayColour(texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb, uExposure), 1.0); }
