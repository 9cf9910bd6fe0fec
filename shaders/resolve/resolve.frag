#version 450 core
// Depth-aware MSAA resolve (Magnussen, "Intra-Model Smoothing Using Depth Aware MSAA for Deferred
// Rendering Pipelines"; FreeSpace Open's shipped variant as WEIGHTING_FSO).
//
// Per pixel: pick a reference sample by depth, weight every sample by how close its depth is to the
// reference (Eq. 1: |d1 - d2| < min(d1, d2) * tan(hfov / width) * c), and write the weighted mean of
// each host attachment into the host's single-sample G-buffer. Samples on one surface are smoothed
// together (intra-model aliasing); samples of other surfaces never mix in, so no pixel is lit at a
// position between two surfaces.
//
#include "common/gbuffer.glsl"

uniform int uWeighting;          // one of WEIGHTING_* (injected from the C++ enum)
uniform float uFootprintTan;     // tan(hfov / width): Eq. 1's pixel footprint per metre
uniform float uFsoFootprintTan;  // tan(hfov / height): FreeSpace Open's footprint
uniform float uCloseness;        // c of Eq. 1

const float kFsoWindow = 2.5;  // FreeSpace Open's window, in pixel footprints
const float kInfinity = 1.0 / 0.0;

// A smooth ramp from 0 at e0 to 1 at e1, for either order of the edges. GLSL's smoothstep is undefined
// for e0 >= e1, which FreeSpace Open's falling edge relies on; this is the ramp it intends.
float ramp(float e0, float e1, float x) {
  float t = clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float distance[SAMPLES];  // metres in front of the camera; +inf for background
  bool usable[SAMPLES];     // false for samples holding NaN or Inf in any attachment
  int order[SAMPLES];       // usable samples sorted near to far
  int usableCount = 0;
  for (int s = 0; s < SAMPLES; ++s) {
    usable[s] = sampleIsFinite(pixel, s);
    distance[s] = sampleDistance(pixel, s);
    if (!usable[s]) continue;
    int i = usableCount++;
    while (i > 0 && distance[order[i - 1]] > distance[s]) {  // insertion sort, N <= 16
      order[i] = order[i - 1];
      --i;
    }
    order[i] = s;
  }

  vec4 values[ATTACHMENT_COUNT];
  if (usableCount == 0) {  // every sample corrupt: write an empty background pixel
    for (int a = 0; a < ATTACHMENT_COUNT; ++a) values[a] = vec4(0.0);
    values[POSITION_ATTACHMENT][DEPTH_CHANNEL] = uBackgroundAbove;
    STORE_OUTPUTS(values);
    gl_FragDepth = 1.0;
    return;
  }

  int reference;
  if (uWeighting == WEIGHTING_FRONT || uWeighting == WEIGHTING_MEAN)
    reference = order[0];
  else if (uWeighting == WEIGHTING_BACK)
    reference = order[usableCount - 1];
  else if (uWeighting == WEIGHTING_FSO)
    reference = order[usableCount - 1 - (usableCount - 1) / 2];  // lower median of ascending view z
  else
    reference = order[(usableCount - 1) / 2];  // a real middle sample: the nearer of two for even N
  float dRef = distance[reference];
  bool referenceIsBackground = isinf(dRef);

  float weight[SAMPLES];
  float weightSum = 0.0;
  for (int s = 0; s < SAMPLES; ++s) {
    float w = 0.0;
    if (usable[s]) {
      bool background = isinf(distance[s]);
      if (referenceIsBackground || background) {
        w = (referenceIsBackground && background) ? 1.0 : 0.0;
      } else if (uWeighting == WEIGHTING_MEAN) {
        w = 1.0;
      } else if (uWeighting == WEIGHTING_FSO) {
        float window = kFsoWindow * dRef * uFsoFootprintTan;
        w = ramp(dRef - 2.0 * window, dRef - window, distance[s]) * ramp(dRef + 2.0 * window, dRef + window, distance[s]);
      } else {
        w = abs(distance[s] - dRef) <= min(distance[s], dRef) * uFootprintTan * uCloseness ? 1.0 : 0.0;
      }
    }
    if (s == reference) w = 1.0;  // the reference always counts (c = 0 keeps only its depth)
    weight[s] = w;
    weightSum += w;
  }

  int contributors = 0;
  for (int s = 0; s < SAMPLES; ++s) contributors += weight[s] > 0.0 ? 1 : 0;
  if (contributors == 1) {  // one sample: pass it through untouched (N = 1 equals `off` bit for bit)
    for (int a = 0; a < ATTACHMENT_COUNT; ++a) values[a] = FETCH(uAttachments[a], pixel, reference);
#if NORMAL_ATTACHMENT >= 0
    values[NORMAL_ATTACHMENT] = safeNormal(values[NORMAL_ATTACHMENT]);
#endif
    STORE_OUTPUTS(values);
    gl_FragDepth = FETCH(uDepthBuffer, pixel, reference).r;
    return;
  }

  float depthSum = 0.0;
  float depthBuffer = 0.0;
  for (int a = 0; a < ATTACHMENT_COUNT; ++a) values[a] = vec4(0.0);
  for (int s = 0; s < SAMPLES; ++s) {
    float w = weight[s] / weightSum;
    if (w <= 0.0) continue;
    for (int a = 0; a < ATTACHMENT_COUNT; ++a) values[a] += w * FETCH(uAttachments[a], pixel, s);
    if (!referenceIsBackground) depthSum += w * distance[s];
    if (referenceIsBackground) depthBuffer = max(depthBuffer, FETCH(uDepthBuffer, pixel, s).r);
  }

  // Depth is averaged in metres and re-encoded: the encoding is not linear above its knee.
  if (!referenceIsBackground) values[POSITION_ATTACHMENT][DEPTH_CHANNEL] = encodeDepth(depthSum);
#if NORMAL_ATTACHMENT >= 0
  vec3 normal = values[NORMAL_ATTACHMENT].xyz;
  float len = length(normal);
  if (!(len > 1e-4)) {  // opposing or zero-length normals: fall back to the reference's, then the view
    normal = FETCH(uAttachments[NORMAL_ATTACHMENT], pixel, reference).xyz;
    len = length(normal);
    if (!(len > 1e-4)) normal = vec3(0.0, 0.0, 1.0), len = 1.0;
  }
  if (!referenceIsBackground) values[NORMAL_ATTACHMENT].xyz = normal / len;
#endif
  STORE_OUTPUTS(values);
  // The reference sample's depth-buffer value (encoding-agnostic), so forward passes after lighting
  // depth-test against the surface that was lit.
  gl_FragDepth = referenceIsBackground ? depthBuffer : FETCH(uDepthBuffer, pixel, reference).r;
}
