#version 450 core
// The forward mask: what the host's forward passes did to each pixel, against the copy of the scene colour
// kept at beginForward(). 0: nothing (a change within 1/256 of the value: the forward target's half-float
// round trip, a blend that adds nothing visible). 0.5: a film, whose change follows the pixels under it
// (a faint particle's smoke, a haze): rebuilding the opaque edge beneath from neighbours under the same film
// spreads nothing visible. 1: an edge of what the passes drew (an opaque particle's, a gizmo's outline),
// whose colour a post pass must neither rebuild nor lend.
layout(binding = 0) uniform sampler2D uBefore;  // the scene colour as shade() left it
layout(binding = 1) uniform sampler2D uAfter;   // the scene colour after the forward passes
out float outDrawn;

// A film changes a pixel by at most this share of how the pixels under it differ, plus its own gradient
// (kFilmGradient of the value per pixel): a particle of a quarter's opacity or less. STK's exhaust smoke
// over olivermath's kart, reconstruct's edge PSNR at 1/64, 1/16, 1/8 and with no bound: 25.14, 25.56, 25.98,
// 26.16 dB; interior 43.11, 43.28, 43.33, 42.90 (a bound of 1/8 keeps a sharp forward edge of 12 % frozen).
const float kFilmOpacity = 0.25, kFilmGradient = 1.0 / 8.0;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy), last = textureSize(uBefore, 0) - 1;
  vec3 before = texelFetch(uBefore, pixel, 0).rgb;
  vec3 after = texelFetch(uAfter, pixel, 0).rgb;
  vec3 scale = max(abs(before), abs(after));
  vec3 change = after - before;
  if (!any(greaterThan(abs(change), max(scale / 256.0, vec3(1e-6))))) {
    outDrawn = 0.0;
    return;
  }
  outDrawn = 0.5;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), last);
      vec3 beforeQ = texelFetch(uBefore, q, 0).rgb, afterQ = texelFetch(uAfter, q, 0).rgb;
      vec3 allowed = kFilmOpacity * abs(beforeQ - before) + kFilmGradient * max(scale, max(abs(beforeQ), abs(afterQ)));
      if (any(greaterThan(abs((afterQ - beforeQ) - change), allowed + 1e-6))) outDrawn = 1.0;
    }
}
