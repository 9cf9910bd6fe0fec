#version 450 core
// SMAA pass 3: neighbourhood blending. Each pixel mixes with the neighbour across its strongest
// edge by the coverage area the weights pass found (the larger of horizontal and vertical wins).
// SMAA_BLEND_MARK 1: MarkedRewrite's marking draw (on the display, SMAA 1x rewrites in place only the
// pixels that have weights of their own or from the neighbours they blend with).
#include "smaa/smaa_common.glsl"
layout(binding = 0) uniform sampler2D uInput;    // the colour the edges were found in
layout(binding = 1) uniform sampler2D uWeights;  // pass 2's areas
out vec4 outColour;

vec4 toLinear(vec4 c) {
#if SMAA_HDR_INPUT
  return c;
#else
  return vec4(displayToLinear(c.rgb), c.a);
#endif
}
vec4 fromLinear(vec4 c) {
#if SMAA_HDR_INPUT
  return c;
#else
  return vec4(linearToDisplay(c.rgb), c.a);
#endif
}
vec4 colourAt(ivec2 p) { return toLinear(texelFetch(uInput, clamp(p, ivec2(0), ivec2(uMetrics.zw) - 1), 0)); }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  // a.x: towards +x (the right neighbour's left edge), a.y: towards +y, a.z: towards −x, a.w: towards −y.
  vec4 a;
  a.x = texelFetch(uWeights, min(p + ivec2(1, 0), ivec2(uMetrics.zw) - 1), 0).a;
  a.y = texelFetch(uWeights, min(p + ivec2(0, 1), ivec2(uMetrics.zw) - 1), 0).g;
  a.wz = texelFetch(uWeights, p, 0).xz;
#if SMAA_BLEND_MARK
  // The first of MarkedRewrite's draws: a pixel without weights keeps its colour and is not written.
  if (dot(a, vec4(1.0)) < 1e-5) discard;
#else
  vec4 centre = texelFetch(uInput, p, 0);
  if (dot(a, vec4(1.0)) < 1e-5) {
    outColour = centre;
    return;
  }
  bool horizontal = max(a.x, a.z) > max(a.y, a.w);
  vec2 weight = horizontal ? a.xz : a.yw;  // towards + and towards −
  ivec2 axis = horizontal ? ivec2(1, 0) : ivec2(0, 1);
  weight /= dot(weight, vec2(1.0));
  // The reference's two bilinear fetches, each centre·(1 − a) + neighbour·a, mixed in linear light.
  vec4 lc = toLinear(centre);
  vec2 amount = horizontal ? vec2(a.x, a.z) : vec2(a.y, a.w);
  vec4 towardsPlus = mix(lc, colourAt(p + axis), amount.x);
  vec4 towardsMinus = mix(lc, colourAt(p - axis), amount.y);
  outColour = fromLinear(weight.x * towardsPlus + weight.y * towardsMinus);
#endif
}
