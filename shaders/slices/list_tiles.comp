#version 450 core
// The tiles of the slice counts, for the passes of the slices that touch only pixels lit more than once
// (SliceRenderer::tilesWhereCountAtLeast). One invocation a TILE x TILE tile (no barrier, nothing shared:
// each reads its tile in 2 x 2 gathers): stores the tile's largest count, and appends the tile to list t
// (1 <= t < SAMPLES) for every t below it, as its rectangle in normalised device coordinates, an instance
// of indirect draw t - 1. A sparse slice then costs its tiles, not a full-screen pass its stencil mostly
// rejects.
layout(local_size_x = GROUP, local_size_y = GROUP) in;
layout(binding = 0) uniform usampler2D uSliceCounts;
layout(binding = 0, r8ui) writeonly uniform uimage2D uTileMaxima;
struct DrawCommand {
  uint vertexCount, instanceCount, firstVertex, baseInstance;  // {6, 0, 0, (t - 1) x tiles} before the pass
};
layout(std430, binding = 0) buffer Commands { DrawCommand commands[]; };
layout(std430, binding = 1) writeonly buffer Rectangles { vec4 rectangles[]; };

void main() {
  ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(tile, imageSize(uTileMaxima)))) return;
  ivec2 size = textureSize(uSliceCounts, 0);
  ivec2 origin = tile * TILE, end = min(origin + TILE, size);
  // A gather's four texels around a corner; past the image's edge it clamps onto texels inside the tile.
  vec2 texel = 1.0 / vec2(size);
  uvec4 maxima = uvec4(0u);
  for (int y = origin.y; y < end.y; y += 2)
    for (int x = origin.x; x < end.x; x += 2)
      maxima = max(maxima, textureGather(uSliceCounts, vec2(x + 1, y + 1) * texel, 0));
  uint maxCount = max(max(maxima.x, maxima.y), max(maxima.z, maxima.w));
  imageStore(uTileMaxima, tile, uvec4(maxCount));
  // Tiles meet at the same computed edge, so no pixel is drawn twice or missed.
  vec4 rectangle = vec4(vec2(origin), vec2(end)) / vec4(size, size) * 2.0 - 1.0;
  for (uint t = 1u; t < min(maxCount, uint(SAMPLES)); ++t) {
    uint at = atomicAdd(commands[t - 1u].instanceCount, 1u);
    rectangles[commands[t - 1u].baseInstance + at] = rectangle;
  }
}
