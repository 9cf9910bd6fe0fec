// Reading the per-sample slice indices written by aggregate/cluster.frag (4 bits per sample).
layout(binding = 14) uniform usampler2D uAssignment;
uint sliceOfSample(uvec2 assignment, int s) {
  return ((s < 8 ? assignment.x : assignment.y) >> uint(4 * (s & 7))) & 15u;
}
