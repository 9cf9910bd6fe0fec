#version 450 core
// Edge detection for `edge` (Thibieroz): a pixel whose samples see more than one surface gets all N
// samples lit (slice count N), any other pixel one (count 1). Writes the count into an R8UI target and,
// where ARB_shader_stencil_export exists, into the stencil buffer in the same pass.
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
#include "common/gbuffer.glsl"

// EDGE_DETECTOR is one of the DETECTOR_* values the plugin injects (shared_constants.h).
uniform float uFootprintTan;     // tan(hfov / width)
uniform float uDepthCloseness;   // c of the depth detector
uniform float uNormalCosine;     // cos(angle) of the normal detector
layout(location = 0) out uint outCount;

bool isEdge(ivec2 pixel) {
#if EDGE_DETECTOR == DETECTOR_EVERY_PIXEL
  return true;
#else
  float d0 = sampleDistance(pixel, 0);
  vec3 n0 = sampleNormal(pixel, 0);
#if EDGE_DETECTOR == DETECTOR_PLANE
  // Lauritzen's tiled-deferred test: the depth slope across the pixel bounds how far its own samples
  // may stray from sample 0's depth.
  float maxDelta = isinf(d0) ? 0.0 : abs(dFdx(d0)) + abs(dFdy(d0));
  if (isnan(maxDelta) || isinf(maxDelta)) maxDelta = 0.0;
#endif
  for (int s = 1; s < SAMPLES; ++s) {
    float d = sampleDistance(pixel, s);
    if (isinf(d) != isinf(d0)) return true;  // geometry beside background
    if (isinf(d)) continue;                  // background beside background
#if EDGE_DETECTOR == DETECTOR_DEPTH
    if (abs(d - d0) > min(d, d0) * uFootprintTan * uDepthCloseness) return true;
#elif EDGE_DETECTOR == DETECTOR_PLANE
    if (abs(d - d0) > maxDelta + 1e-5 * d0 || dot(sampleNormal(pixel, s), n0) < 0.99) return true;
#elif EDGE_DETECTOR == DETECTOR_NORMAL
    if (dot(normalize(sampleNormal(pixel, s)), normalize(n0)) < uNormalCosine) return true;
#elif EDGE_DETECTOR == DETECTOR_MATERIAL
    // The material channels the layout has: albedo, specular, and gloss beside an xyz normal.
    bool differs = false;
#if ALBEDO_ATTACHMENT >= 0
    differs = differs || any(greaterThan(abs(FETCH(uAttachments[ALBEDO_ATTACHMENT], pixel, s) -
                                             FETCH(uAttachments[ALBEDO_ATTACHMENT], pixel, 0)), vec4(1.0 / 512.0)));
#endif
#if SPECULAR_ATTACHMENT >= 0
    differs = differs || any(greaterThan(abs(FETCH(uAttachments[SPECULAR_ATTACHMENT], pixel, s) -
                                             FETCH(uAttachments[SPECULAR_ATTACHMENT], pixel, 0)), vec4(1.0 / 512.0)));
#endif
#if NORMAL_ATTACHMENT >= 0 && NORMAL_ENCODING == NORMAL_XYZ
    differs = differs || abs(FETCH(uAttachments[NORMAL_ATTACHMENT], pixel, s).w -
                             FETCH(uAttachments[NORMAL_ATTACHMENT], pixel, 0).w) > 1.0 / 512.0;
#endif
#if NORMAL_ATTACHMENT >= 0 && NORMAL_ENCODING == NORMAL_SPHEREMAP  // zw: the host's material (STK: roughness, metallic)
    differs = differs || any(greaterThan(abs(FETCH(uAttachments[NORMAL_ATTACHMENT], pixel, s).zw -
                                             FETCH(uAttachments[NORMAL_ATTACHMENT], pixel, 0).zw), vec2(1.0 / 512.0)));
#endif
    if (differs) return true;
#elif EDGE_DETECTOR == DETECTOR_COVERAGE
    // The host's model shader runs once per pixel and primitive; every sample one primitive covers
    // holds its outputs bit for bit. Any difference means a second primitive.
    for (int a = 0; a < ATTACHMENT_COUNT; ++a)
      if (FETCH(uAttachments[a], pixel, s) != FETCH(uAttachments[a], pixel, 0)) return true;
#endif
  }
  return false;
#endif
}

void main() {
  int count = isEdge(ivec2(gl_FragCoord.xy)) ? SAMPLES : 1;
  outCount = uint(count);
#if STENCIL_EXPORT
  gl_FragStencilRefARB = count;
#endif
}
