// Reading the per-sample slice indices written by aggregate/cluster.frag: 3 bits per sample (NO_SLICE
// for a sample no aggregate holds), samples 0-9 in x and 10-15 in y; y's top bit marks a pixel whose one
// aggregate the resolve already holds (RESOLVE_HOLDS_AGGREGATE).
layout(binding = UNIT_SLICE_WEIGHTS) uniform usampler2D uAssignment;
const uint RESOLVE_HOLDS_AGGREGATE = 1u << 31;
uint sliceOfSample(uvec2 assignment, int s) {
  return ((s < 10 ? assignment.x : assignment.y) >> uint(3 * (s < 10 ? s : s - 10))) & 7u;
}
