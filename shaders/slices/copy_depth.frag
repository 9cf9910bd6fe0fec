#version 450 core
// A composing layout's slices keep their depth where the host's callback tests it (a sky at the far
// plane): before the slices, every pixel's resolved depth, which slice 0 keeps where it lights the
// resolved G-buffer; each slice then writes its own samples' depth over it.
layout(binding = 0) uniform sampler2D uDepth;
void main() { gl_FragDepth = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r; }
