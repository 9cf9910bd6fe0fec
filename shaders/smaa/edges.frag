#version 450 core
// SMAA pass 1: edge detection. r: an edge between this pixel and its left neighbour; g: between it
// and the neighbour at y − 1. An edge needs a contrast above SMAA_THRESHOLD, and survives only if no
// neighbouring edge has SMAA_LOCAL_CONTRAST_ADAPTATION_FACTOR times its contrast (the paper's local
// contrast adaptation, which removes spurious crossing edges). Pixels without edges discard: the
// target was cleared to 0. SMAA_EDGE_MODE: 0 luma, 1 colour (max channel difference), 2 depth (the
// host's view depth from its G-buffer: a relative step above 0.1 × threshold).
#include "smaa/smaa_common.glsl"
#if SMAA_EDGE_MODE == 2
#include "common/depth.glsl"
#include "common/depth_buffer.glsl"
#endif
// Colour; in depth mode the host's position attachment (DepthSource::PositionChannel), else its depth texture.
layout(binding = 0) uniform sampler2D uInput;
out vec2 outEdges;

#define SMAA_LOCAL_CONTRAST_ADAPTATION_FACTOR 2.0

#if SMAA_EDGE_MODE == 0
float contrast(vec3 a, vec3 b) { return abs(dot(a - b, vec3(0.2126, 0.7152, 0.0722))); }
#else
float contrast(vec3 a, vec3 b) {
  vec3 t = abs(a - b);
  return max(max(t.r, t.g), t.b);
}
#endif

vec3 valueAt(ivec2 p) {
  p = clamp(p, ivec2(0), ivec2(uMetrics.zw) - 1);
#if SMAA_EDGE_MODE == 2
  // Background counts as very far, so every silhouette against it is a step.
#if DEPTH_SOURCE != DEPTH_SOURCE_POSITION_CHANNEL  // the depth buffer
  float z = texelFetch(uInput, p, 0).r;
  return vec3(depthBufferIsFar(z) ? 1e30 : depthBufferToMetres(z));
#else
  float stored = texelFetch(uInput, p, 0)[DEPTH_CHANNEL];
  return vec3(isBackground(stored) ? 1e30 : decodeDepth(stored));
#endif
#else
  return perceptual(texelFetch(uInput, p, 0).rgb);
#endif
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 centre = valueAt(p), left = valueAt(p + ivec2(-1, 0)), below = valueAt(p + ivec2(0, -1));
#if SMAA_EDGE_MODE == 2
  float nearest = max(min(centre.x, min(left.x, below.x)), 1e-6);
  vec2 delta = abs(centre.x - vec2(left.x, below.x)) / nearest;
  vec2 edges = step(vec2(0.1 * SMAA_THRESHOLD), delta);
  if (dot(edges, vec2(1.0)) == 0.0) discard;
  outEdges = edges;
#else
  vec4 delta;
  delta.xy = vec2(contrast(centre, left), contrast(centre, below));
  vec2 edges = step(vec2(SMAA_THRESHOLD), delta.xy);
  if (dot(edges, vec2(1.0)) == 0.0) discard;

  // Local contrast adaptation: the largest contrast around both edges.
  delta.zw = vec2(contrast(centre, valueAt(p + ivec2(1, 0))), contrast(centre, valueAt(p + ivec2(0, 1))));
  vec2 maxDelta = max(delta.xy, delta.zw);
  delta.zw = vec2(contrast(left, valueAt(p + ivec2(-2, 0))), contrast(below, valueAt(p + ivec2(0, -2))));
  maxDelta = max(maxDelta, delta.zw);
  float finalDelta = max(maxDelta.x, maxDelta.y);
  outEdges = edges * step(finalDelta, SMAA_LOCAL_CONTRAST_ADAPTATION_FACTOR * delta.xy);
#endif
}
