#version 450 core
// The forward target before the host's forward passes: every sample the slices did not keep (alpha 0)
// takes its pixel's scene colour, blended in with (1 - destination alpha) so that kept samples stay; a
// pixel the forward passes do not touch resolves back to its scene colour.
layout(binding = 0) uniform sampler2D uSceneColour;
out vec4 outColour;
void main() { outColour = texelFetch(uSceneColour, ivec2(gl_FragCoord.xy), 0); }
