// Access to the plugin's multisampled copy of the host G-buffer. The plugin prepends the layout's
// #defines (MsaaGBuffer::shaderDefines): SAMPLES, MULTISAMPLED, ATTACHMENT_COUNT, the attachment
// indices by role, DEPTH_CHANNEL, DEPTH_ENCODING, the outputs out0..outK and STORE_OUTPUTS(values).
#include "common/depth.glsl"

#if MULTISAMPLED
#define GBUFFER_SAMPLER sampler2DMS
#define FETCH(textureName, pixel, s) texelFetch(textureName, pixel, s)
#else  // N = 1 uses plain textures
#define GBUFFER_SAMPLER sampler2D
#define FETCH(textureName, pixel, s) texelFetch(textureName, pixel, 0)
#endif
layout(binding = 0) uniform GBUFFER_SAMPLER uAttachments[ATTACHMENT_COUNT];
layout(binding = UNIT_DEPTH_STENCIL) uniform GBUFFER_SAMPLER uDepthBuffer;  // the MSAA depth buffer (encoding-agnostic)

// View depth of sample s in metres; +inf for background (and for NaN, which reads as background).
float distanceOfStored(float stored) {
  if (isBackground(stored)) return 1.0 / 0.0;
  float d = decodeDepth(stored);
  return d > 0.0 ? d : 1.0 / 0.0;
}
float sampleDistance(ivec2 pixel, int s) {
  return distanceOfStored(FETCH(uAttachments[POSITION_ATTACHMENT], pixel, s)[DEPTH_CHANNEL]);
}

bool sampleIsFinite(ivec2 pixel, int s) {
  uvec4 nonFinite = uvec4(0u);
  for (int a = 0; a < ATTACHMENT_COUNT; ++a) nonFinite |= nonFiniteLanes(FETCH(uAttachments[a], pixel, s));
  return all(equal(nonFinite, uvec4(0u)));
}

#if NORMAL_ATTACHMENT >= 0
// A sample written for the host's lighting: on geometry, a zero-length normal (which a host that
// normalises it would turn into NaN) becomes one facing the camera. A background sample is no surface:
// its values stay as the host cleared them, so the host's lighting treats it as it treats its own
// background pixels. Everything else is left bit for bit.
vec4 safeNormal(vec4 normalGloss, vec4 position) {
  if (isBackground(position[DEPTH_CHANNEL])) return normalGloss;
  return dot(normalGloss.xyz, normalGloss.xyz) > 0.0 ? normalGloss : vec4(0.0, 0.0, 1.0, normalGloss.w);
}
#endif
