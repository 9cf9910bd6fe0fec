#version 450 core
// The compute resolve's depth (resolve.comp) into the host's depth buffer: the one part of the resolve
// an image store cannot write.
layout(binding = 0) uniform sampler2D uResolvedDepth;

void main() { gl_FragDepth = texelFetch(uResolvedDepth, ivec2(gl_FragCoord.xy), 0).r; }
