#version 450 core
layout(binding = 4) uniform sampler2D uEmissive;
out vec4 outLight;
void main() { outLight = vec4(texelFetch(uEmissive, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
