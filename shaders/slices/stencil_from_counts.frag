#version 450 core
// The slice counts already written (the counting resolve's) into the stencil mask, in one pass that reads
// a byte a pixel (where the context has ARB_shader_stencil_export; mark_pixels.frag otherwise).
#extension GL_ARB_shader_stencil_export : require
layout(binding = 1) uniform usampler2D uSliceCounts;
void main() { gl_FragStencilRefARB = int(texelFetch(uSliceCounts, ivec2(gl_FragCoord.xy), 0).r); }
