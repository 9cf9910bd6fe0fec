#version 450 core
// A pass's floor (plugin/src/pass_floor.h): the pass's inputs (FLOOR_INPUTS, units 0, 1, …), each texel
// and sample it reads fetched once into `sum` (FLOOR_READ), written to the pass's outputs (FLOOR_OUTPUTS,
// FLOOR_WRITE): the same fetches and writes as the pass, no other work.
FLOOR_INPUTS
FLOOR_OUTPUTS

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 sum = vec4(0.0);
  FLOOR_READ
  FLOOR_WRITE
}
