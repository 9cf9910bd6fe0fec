// Reading the per-sample slice indices written by aggregate/cluster.frag (4 bits per sample;
// NO_SLICE for a sample no aggregate holds).
layout(binding = UNIT_SLICE_WEIGHTS) uniform usampler2D uAssignment;
uint sliceOfSample(uvec2 assignment, int s) {
  return ((s < 8 ? assignment.x : assignment.y) >> uint(4 * (s & 7))) & 15u;
}
