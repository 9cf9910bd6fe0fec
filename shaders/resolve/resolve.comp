#version 450 core
// The resolve (resolve.glsl) as a compute pass, one 8×8 tile per work group: the host's attachments
// through image stores, the depth into an R32F image that write_depth.frag copies into the host's depth
// buffer (a depth texture takes no image stores). On GPUs whose pixel shaders run on a small graphics
// partition (NVIDIA's H100) a compute pass reaches every multiprocessor.
#include "resolve/resolve.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) writeonly uniform image2D uOutputs[ATTACHMENT_COUNT];  // the host's attachments
layout(binding = ATTACHMENT_COUNT, r32f) writeonly uniform image2D uResolvedDepth;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(uResolvedDepth)))) return;
  vec4 values[ATTACHMENT_COUNT];
  float depth;
  resolvePixel(pixel, values, depth);
#define STORE_ATTACHMENT(a) imageStore(uOutputs[a], pixel, values[a]);
  FOR_EACH_ATTACHMENT(STORE_ATTACHMENT)
  imageStore(uResolvedDepth, pixel, vec4(depth));
}
