#version 450 core
// The reconstruction (reconstruct.glsl) as a compute pass, one 8×8 tile per work group. About one pixel
// in twenty needs rebuilding, along the edges; in a full-screen pass each of them holds up the SIMD
// lanes of its neighbours through the whole ring search. Here the tile first lists its pixels that need
// it, then its invocations take the listed pixels one each: the search runs on packed lanes. Pixels
// not listed are not written; the output already holds them.
#include "reconstruct/reconstruct.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) writeonly uniform image2D uOutput;  // the image uInput is a copy of

shared uint listed[64];  // local invocation indices of the tile's pixels that need rebuilding
shared uint listedCount;

void main() {
  if (gl_LocalInvocationIndex == 0u) listedCount = 0u;
  barrier();
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(pixel, textureSize(uInput, 0))) && !allOnOwnSurface(pixel))
    listed[atomicAdd(listedCount, 1u)] = gl_LocalInvocationIndex;
  barrier();
  for (uint i = gl_LocalInvocationIndex; i < listedCount; i += 64u) {
    ivec2 listedPixel = ivec2(gl_WorkGroupID.xy * 8u + uvec2(listed[i] % 8u, listed[i] / 8u));
    bool changed;
    vec4 result = reconstructPixel(listedPixel, changed);
    imageStore(uOutput, listedPixel, result);
  }
}
