#version 450 core
// The resolve (resolve.glsl) as a full-screen pass: the host's attachments through the outputs, its
// depth through gl_FragDepth. With RESOLVE_COUNTS, `edge`'s detector (edge/detector.glsl) also runs on
// the samples just fetched and writes the pixel's slice count after the attachments: the edge mask
// without a pass that reads every sample again.
#include "resolve/resolve.glsl"
#if RESOLVE_COUNTS
#define DETECTOR_VALUE(a, s) SAMPLE_VALUE(a, s)
#include "edge/detector.glsl"
layout(location = ATTACHMENT_COUNT) out uint outCount;
#endif
#ifdef RESOLVE_KEPT_DEPTH_LOCATION
// The depth as written below, for the restore after the slices (ResolvePass::keepForRestore):
// write_depth.frag writes these very floats again, and the depth buffer stores them as it did here.
layout(location = RESOLVE_KEPT_DEPTH_LOCATION) out float outKeptDepth;
#endif

void main() {
  // A helper fragment beyond the last column or row reads the last one (the detector's quad exchange).
  ivec2 pixel = min(ivec2(gl_FragCoord.xy), gbufferPixels() - 1);
  vec4 values[ATTACHMENT_COUNT];
  float depth;
  resolvePixel(pixel, values, depth);
  STORE_OUTPUTS(values);
#if RESOLVE_COUNTS
  outCount = uint(isEdge(pixel) ? SAMPLES : 1);
#endif
  // The restore after the slices (RESOLVE_RESTORE) leaves the depth as it is: without a depth output the
  // stencil test that limits it to the slices' pixels runs before the shader.
#ifndef RESOLVE_RESTORE
  gl_FragDepth = depth;
#endif
#ifdef RESOLVE_KEPT_DEPTH_LOCATION
  outKeptDepth = depth;
#endif
}
