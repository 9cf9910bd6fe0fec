#version 450 core
// An averaged radiance shown on the display (ground truth): the sRGB target encodes it.
layout(binding = 0) uniform sampler2D uRadiance;
out vec4 outColour;
void main() { outColour = vec4(texelFetch(uRadiance, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
