// Access to the plugin's multisampled copy of the host G-buffer. The plugin prepends the layout's
// #defines (MsaaGBuffer::shaderDefines): SAMPLES, MULTISAMPLED, ATTACHMENT_COUNT, the attachment
// indices by role, DEPTH_SOURCE, DEPTH_CHANNEL, DEPTH_ENCODING, DEPTH_BUFFER_ENCODING, NORMAL_ENCODING,
// the outputs out0..outK, STORE_OUTPUTS(values) and FOR_EACH_ATTACHMENT(M) (M(0) M(1) ...: constant
// indices, which an array of the attachments needs to stay in registers).
#include "common/depth.glsl"
#include "common/depth_buffer.glsl"
#include "common/normal.glsl"

#if SUPERSAMPLE > 1  // an m×m window of a supersampled G-buffer per pixel, sub-position s at (s mod m, s div m)
#define GBUFFER_SAMPLER sampler2D
#define FETCH(textureName, pixel, s) \
  texelFetch(textureName, (pixel) * SUPERSAMPLE + ivec2((s) % SUPERSAMPLE, (s) / SUPERSAMPLE), 0)
#elif MULTISAMPLED
#define GBUFFER_SAMPLER sampler2DMS
#define FETCH(textureName, pixel, s) texelFetch(textureName, pixel, s)
#else  // N = 1 uses plain textures
#define GBUFFER_SAMPLER sampler2D
#define FETCH(textureName, pixel, s) texelFetch(textureName, pixel, 0)
#endif
layout(binding = 0) uniform GBUFFER_SAMPLER uAttachments[ATTACHMENT_COUNT];
layout(binding = UNIT_DEPTH_STENCIL) uniform GBUFFER_SAMPLER uDepthBuffer;  // the MSAA depth buffer (encoding-agnostic)

// The G-buffer's size in pixels (a supersampled one holds SUPERSAMPLE² texels a pixel).
ivec2 gbufferPixels() {
#if SUPERSAMPLE > 1
  return textureSize(uDepthBuffer, 0) / SUPERSAMPLE;
#elif MULTISAMPLED
  return textureSize(uDepthBuffer);
#else
  return textureSize(uDepthBuffer, 0);
#endif
}

// View depth of sample s in metres; +inf for background (and for NaN, which reads as background).
float distanceOfStored(float stored) {
  if (isBackground(stored)) return 1.0 / 0.0;
  float d = decodeDepth(stored);
  return d > 0.0 ? d : 1.0 / 0.0;
}
float distanceOfDepthBuffer(float z) {
  if (depthBufferIsFar(z)) return 1.0 / 0.0;
  float d = depthBufferToMetres(z);
  return d > 0.0 ? d : 1.0 / 0.0;
}
// A world-space position's distance in front of the camera; +inf behind it.
float distanceOfWorld(vec3 p) {
  float d = -dot(uViewDepthRow, vec4(p, 1.0));
  return d > 0.0 ? d : 1.0 / 0.0;
}
#if DEPTH_SOURCE == DEPTH_SOURCE_DEPTH_BUFFER
float sampleDistance(ivec2 pixel, int s) { return distanceOfDepthBuffer(FETCH(uDepthBuffer, pixel, s).r); }
// Whether the host marked sample s as "no geometry" (its own background, left as the host cleared it).
bool sampleMarkedBackground(ivec2 pixel, int s) { return depthBufferIsFar(FETCH(uDepthBuffer, pixel, s).r); }
#elif DEPTH_SOURCE == DEPTH_SOURCE_WORLD_POSITION
bool sampleMarkedBackground(ivec2 pixel, int s) { return depthBufferIsFar(FETCH(uDepthBuffer, pixel, s).r); }
float sampleDistance(ivec2 pixel, int s) {
  if (sampleMarkedBackground(pixel, s)) return 1.0 / 0.0;
  return distanceOfWorld(FETCH(uAttachments[POSITION_ATTACHMENT], pixel, s).xyz);
}
#else
float sampleDistance(ivec2 pixel, int s) {
  return distanceOfStored(FETCH(uAttachments[POSITION_ATTACHMENT], pixel, s)[DEPTH_CHANNEL]);
}
bool sampleMarkedBackground(ivec2 pixel, int s) {
  return isBackground(FETCH(uAttachments[POSITION_ATTACHMENT], pixel, s)[DEPTH_CHANNEL]);
}
#endif

// Sample s's normal, decoded (NormalEncoding); facing the camera where the layout has none.
vec3 sampleNormal(ivec2 pixel, int s) {
#if NORMAL_ATTACHMENT >= 0
  return decodeNormal(FETCH(uAttachments[NORMAL_ATTACHMENT], pixel, s));
#else
  return vec3(0.0, 0.0, 1.0);
#endif
}

bool sampleIsFinite(ivec2 pixel, int s) {
  uvec4 nonFinite = uvec4(0u);
#define OR_NON_FINITE_ATTACHMENT(a) nonFinite |= nonFiniteLanes(FETCH(uAttachments[a], pixel, s));
  FOR_EACH_ATTACHMENT(OR_NON_FINITE_ATTACHMENT)
  return all(equal(nonFinite, uvec4(0u)));
}

// A sample written for the host's lighting: on geometry, a zero-length normal (which a host that
// normalises it would turn into NaN) becomes one facing the camera. A background sample is no surface:
// its values stay as the host cleared them, so the host's lighting treats it as it treats its own
// background pixels. Everything else is left bit for bit.
vec4 safeNormal(vec4 normalGloss, bool markedBackground) {
  if (!kNormalCanBeZero || markedBackground) return normalGloss;
  return dot(normalGloss.xyz, normalGloss.xyz) > 0.0 ? normalGloss : vec4(0.0, 0.0, 1.0, normalGloss.w);
}

// The depth writes of the slices (WRITE_DEPTH: DepthSource::DepthBuffer): a slice's writer runs again
// into the host's depth texture, limited by the counts to the pixels the slice writes (a count of at
// least uMinCount; 0: every pixel).
#ifdef WRITE_DEPTH
layout(binding = UNIT_SLICE_COUNTS) uniform usampler2D uSliceCountsOfDepth;
uniform int uMinCount;
void limitDepthWriteToSlice(ivec2 pixel) {
  if (uMinCount > 0 && int(texelFetch(uSliceCountsOfDepth, pixel, 0).r) < uMinCount) discard;
}
#define STORE_SLICE_DEPTH(value) gl_FragDepth = (value)
#else
void limitDepthWriteToSlice(ivec2 pixel) {}
#define STORE_SLICE_DEPTH(value)
#endif
