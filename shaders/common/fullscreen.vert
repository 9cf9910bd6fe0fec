#version 450 core
// One triangle covering the viewport, or the tiles of a sparse pass (PluginContext::drawTiles): each
// instance's rectangle comes from the bound vertex array, (-1, -1, 3, 3) for the whole screen, whose
// first three corners are the full-screen triangle; a tile draws six, two triangles.
layout(location = 0) in vec4 aRectangle;  // x0, y0, x1, y1 in normalised device coordinates
void main() {
  const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(0, 1), vec2(1, 0), vec2(1, 1));
  gl_Position = vec4(mix(aRectangle.xy, aRectangle.zw, corners[gl_VertexID]), 0.0, 1.0);
}
