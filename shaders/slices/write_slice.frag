#version 450 core
// Slice s: sample s of each pixel, copied verbatim into the host's single-sample G-buffer so the host's
// unchanged lighting can light it. The stencil test (count > s) keeps other pixels untouched. A sample
// with NaN or Inf anywhere is skipped: the pixel keeps the previous slice's (finite) values; a
// zero-length normal on geometry is replaced by one facing the camera (background samples are left as
// the host cleared them). WRITE_DEPTH (DepthSource::DepthBuffer) runs it again into the host's depth
// texture, which the host's lighting rebuilds positions from.
#include "common/gbuffer.glsl"
uniform int uSample;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  limitDepthWriteToSlice(pixel);
  if (!sampleIsFinite(pixel, uSample)) discard;
  vec4 values[ATTACHMENT_COUNT];
#define COPY_SAMPLE(a) values[a] = FETCH(uAttachments[a], pixel, uSample);
  FOR_EACH_ATTACHMENT(COPY_SAMPLE)
#if NORMAL_ATTACHMENT >= 0
  values[NORMAL_ATTACHMENT] = safeNormal(values[NORMAL_ATTACHMENT], sampleMarkedBackground(pixel, uSample));
#endif
  STORE_OUTPUTS(values);
  STORE_SLICE_DEPTH(FETCH(uDepthBuffer, pixel, uSample).r);
}
