#version 450 core
// A compute pass's floor (plugin/src/pass_floor.h): floor.frag's fetches and writes, one invocation per
// pixel in the pass's own work groups, the outputs through image stores.
layout(local_size_x = FLOOR_TILE, local_size_y = FLOOR_TILE) in;
FLOOR_INPUTS
FLOOR_OUTPUTS

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, FLOOR_SIZE))) return;
  vec4 sum = vec4(0.0);
  FLOOR_READ
  FLOOR_WRITE
}
