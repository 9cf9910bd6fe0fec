#version 450 core
// Aggregate `uSlice` of each pixel as one G-buffer sample: mean albedo, specular, emissive, position
// (depth averaged in metres), mean normal renormalised; where the layout has a gloss channel, gloss is
// lowered by the spread of the normals (Toksvig: a shorter mean normal means a blurrier highlight).
#include "common/gbuffer.glsl"
#include "aggregate/aggregate.glsl"
uniform int uSlice;
uniform int uHasGloss;
uniform float uGlossScale;  // the layout's gloss: specular exponent = exp2(gloss · scale + bias)
uniform float uGlossBias;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  limitDepthWriteToSlice(pixel);
  uvec2 assignment = texelFetch(uAssignment, pixel, 0).xy;
  if ((assignment.y & RESOLVE_HOLDS_AGGREGATE) != 0u) discard;  // the resolved G-buffer is its mean already
  vec4 values[ATTACHMENT_COUNT];
#define CLEAR_ATTACHMENT(a) values[a] = vec4(0.0);
  FOR_EACH_ATTACHMENT(CLEAR_ATTACHMENT)
  float depthSum = 0.0, count = 0.0;
  vec3 normalSum = vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    if (sliceOfSample(assignment, s) != uint(uSlice)) continue;
#define ADD_SAMPLE(a) values[a] += FETCH(uAttachments[a], pixel, s);
    FOR_EACH_ATTACHMENT(ADD_SAMPLE)
    depthSum += sampleDistance(pixel, s);
#if NORMAL_ATTACHMENT >= 0
    vec3 n = sampleNormal(pixel, s);
    normalSum += dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);  // as the clustering treats it
#endif
    count += 1.0;
  }
  if (count == 0.0) discard;
#define DIVIDE_ATTACHMENT(a) values[a] /= count;
  FOR_EACH_ATTACHMENT(DIVIDE_ATTACHMENT)
  float meanDepth = depthSum / count;
  STORE_SLICE_DEPTH(isinf(meanDepth) ? kDepthBufferFar : metresToDepthBuffer(meanDepth));
  if (!isinf(meanDepth)) {  // background aggregates keep their (averaged) marker
#if DEPTH_SOURCE == DEPTH_SOURCE_POSITION_CHANNEL
    values[POSITION_ATTACHMENT][DEPTH_CHANNEL] = encodeDepth(meanDepth);
#endif
#if NORMAL_ATTACHMENT >= 0
    float length = length(normalSum) / count;
    values[NORMAL_ATTACHMENT] =
        encodeNormal(values[NORMAL_ATTACHMENT], length > 1e-4 ? normalize(normalSum) : vec3(0.0, 0.0, 1.0));
    if (uHasGloss != 0) {
      float exponent = exp2(values[NORMAL_ATTACHMENT].w * uGlossScale + uGlossBias);
      float widened = length * exponent / (length + exponent * (1.0 - length));  // Toksvig 2004
      values[NORMAL_ATTACHMENT].w = clamp((log2(max(widened, 1e-6)) - uGlossBias) / uGlossScale, 0.0, 1.0);
    }
#endif
  }
  STORE_OUTPUTS(values);
}
