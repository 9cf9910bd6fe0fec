// Depth-aware MSAA resolve (Magnussen, "Intra-Model Smoothing Using Depth Aware MSAA for Deferred
// Rendering Pipelines"), and FreeSpace Open's own resolve (msaa-f.sdr) as WEIGHTING_FSO.
//
// Per pixel: pick a reference sample by depth, weight every sample by how close its depth is to the
// reference (Eq. 1: |d1 - d2| < min(d1, d2) * tan(hfov / width) * c), and write the weighted mean of
// each host attachment into the host's single-sample G-buffer. Samples on one surface are smoothed
// together (intra-model aliasing); samples of other surfaces never mix in, so no pixel is lit at a
// position between two surfaces.
//
// WEIGHTING_FSO computes what FreeSpace Open's shader computes (docs/methods/resolve.md lists the
// facts and the two deviations: corrupt samples are dropped, background normals stay unnormalised).
#include "common/gbuffer.glsl"

// RESOLVE_WEIGHTING: one of WEIGHTING_* (the C++ enum's values), injected as a constant: a uniform would
// leave every weighting's arithmetic in the program, and llvmpipe runs a branch's both sides.

uniform bool uSplitByNeighbours; // resolve_even_split: an even split decided by the 3x3 neighbourhood
uniform float uFootprintTan;     // tan(hfov / width): Eq. 1's pixel footprint per metre
uniform float uFsoFootprintTan;  // tan(vfov / height): FreeSpace Open's texelWidthFactor
uniform float uCloseness;        // c of Eq. 1

const float kWindowFull = 2.5;  // WEIGHTING_WINDOW: full weight within this many footprints,
const float kWindowEnd = 5.0;   // none past this many

// GLSL's smoothstep as Mesa and NVIDIA evaluate it, t = clamp((x - e0) / (e1 - e0)), for either order
// of the edges: GLSL leaves e0 >= e1 undefined, and FreeSpace Open's second edge pair is reversed.
float smoothRamp(float e0, float e1, float x) {
  float t = clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// FreeSpace Open's weight of a sample at view z `z` around its median view z `dist` (both negative in
// front, 0 for background). In footprints u behind the median it is S((u + 2.5) / 7.5) · S((5 - u) / 2.5):
// 0.26 at the median itself, 0.76 at its peak 2.7 behind, 0 nearer than -2.5 or farther than 5.
float fsoWeight(float dist, float z) {
  if (dist >= -0.001) return z >= -0.001 ? 1.0 : 0.0;  // a background median keeps background only
  float footprint = dist * uFsoFootprintTan;
  return smoothRamp(dist + footprint * 5.0, dist + footprint * 2.5, z) *
         smoothRamp(dist - footprint * 2.5, dist + footprint * 5.0, z);
}

// Every sample of every attachment is fetched once, up to 8 samples (80 vec4s at 16 would spill
// registers, so 16 fetches again where it reads). Every array below is indexed only by loop counters
// over constant bounds, which unroll (ranks instead of a sort): an index computed from data may put
// the arrays in scratch memory.
#if SAMPLES <= 8
vec4 fetched[SAMPLES][ATTACHMENT_COUNT];
float fetchedDepthBuffer[SAMPLES];
#define SAMPLE_VALUE(a, s) fetched[s][a]
#define SAMPLE_DEPTH_BUFFER(s) fetchedDepthBuffer[s]
#else
#define SAMPLE_VALUE(a, s) FETCH(uAttachments[a], pixel, s)
#define SAMPLE_DEPTH_BUFFER(s) FETCH(uDepthBuffer, pixel, s).r
#endif
// A sample's view distance and whether the host marked it as background, from the cached values.
#if DEPTH_SOURCE == DEPTH_SOURCE_DEPTH_BUFFER
#define SAMPLE_DISTANCE(s) distanceOfDepthBuffer(SAMPLE_DEPTH_BUFFER(s))
#define SAMPLE_MARKED_BACKGROUND(s) depthBufferIsFar(SAMPLE_DEPTH_BUFFER(s))
#elif DEPTH_SOURCE == DEPTH_SOURCE_WORLD_POSITION
#define SAMPLE_MARKED_BACKGROUND(s) depthBufferIsFar(SAMPLE_DEPTH_BUFFER(s))
#define SAMPLE_DISTANCE(s) \
  (SAMPLE_MARKED_BACKGROUND(s) ? 1.0 / 0.0 : distanceOfWorld(SAMPLE_VALUE(POSITION_ATTACHMENT, s).xyz))
#else
#define SAMPLE_DISTANCE(s) distanceOfStored(SAMPLE_VALUE(POSITION_ATTACHMENT, s)[DEPTH_CHANNEL])
#define SAMPLE_MARKED_BACKGROUND(s) isBackground(SAMPLE_VALUE(POSITION_ATTACHMENT, s)[DEPTH_CHANNEL])
#endif

// A sample's view distance at another pixel, as SAMPLE_DISTANCE gives it here (+inf for background).
float distanceAt(ivec2 q, int s) {
#if DEPTH_SOURCE == DEPTH_SOURCE_DEPTH_BUFFER
  return distanceOfDepthBuffer(FETCH(uDepthBuffer, q, s).r);
#elif DEPTH_SOURCE == DEPTH_SOURCE_WORLD_POSITION
  return depthBufferIsFar(FETCH(uDepthBuffer, q, s).r) ? 1.0 / 0.0
                                                       : distanceOfWorld(FETCH(uAttachments[POSITION_ATTACHMENT], q, s).xyz);
#else
  return distanceOfStored(FETCH(uAttachments[POSITION_ATTACHMENT], q, s)[DEPTH_CHANNEL]);
#endif
}

// A pixel split evenly between two surfaces (2 of 4 samples on each): its own samples cannot say which
// covers more of it, whatever the edge's slope. Its 3x3 block can: a feature thinner than a pixel, or
// one ending there, leaves few of the neighbours' samples on its side. True when no more of the eight
// neighbours' samples lie before the split than beyond it (measured on the hosts that light into their
// display: with the tie given to the nearer surface the window-lit consumer's model edges were 0.95 dB
// worse).
//
// One neighbour's sample per iteration, `fetches` of them (0 where the pixel is not such a split): a
// branch costs llvmpipe both of its sides under a mask, so 8 x SAMPLES fetches written out, inside an
// `if`, or in a loop that runs at most once (NIR makes it an `if`), cost every pixel; a loop whose count
// the compiler cannot know is skipped by a group of pixels none of which enters it. False where `fetches`
// is 0.
bool fartherSurfaceCoversMore(ivec2 pixel, float nearMiddle, float farMiddle, int fetches) {
  float split = isinf(farMiddle) ? farMiddle : 0.5 * (nearMiddle + farMiddle);
  ivec2 last = gbufferPixels() - 1;
  int balance = 0;
  for (int k = 0; k < fetches; ++k) {
    int neighbour = k / SAMPLES;
    neighbour += neighbour >= 4 ? 1 : 0;  // the 3x3 block's cells but its centre (4)
    ivec2 q = clamp(pixel + ivec2(neighbour % 3 - 1, neighbour / 3 - 1), ivec2(0), last);
    balance += distanceAt(q, k % SAMPLES) < split ? 1 : -1;  // NaN: beyond
  }
  return fetches > 0 && balance <= 0;
}

// The resolved values of `pixel`: one per host attachment, and the value for the host's depth buffer.
void resolvePixel(ivec2 pixel, out vec4 values[ATTACHMENT_COUNT], out float depth) {
#if SAMPLES <= 8
  for (int s = 0; s < SAMPLES; ++s) {
#define FETCH_ATTACHMENT(a) fetched[s][a] = FETCH(uAttachments[a], pixel, s);
    FOR_EACH_ATTACHMENT(FETCH_ATTACHMENT)
    fetchedDepthBuffer[s] = FETCH(uDepthBuffer, pixel, s).r;
  }
#endif
  bool fso = RESOLVE_WEIGHTING == WEIGHTING_FSO;
  float distance[SAMPLES];  // metres in front of the camera; +inf for background
  bool usable[SAMPLES];     // false for samples holding NaN or Inf in any attachment
  // Sorted near to far (background farthest, but nearest for FSO, whose background has view z 0):
  // a sample's rank is its place in that order among the usable samples, ties kept in index order.
  float sortKey[SAMPLES];
  int usableCount = 0;
  for (int s = 0; s < SAMPLES; ++s) {
    uvec4 nonFinite = uvec4(0u);
#define OR_NON_FINITE_VALUE(a) nonFinite |= nonFiniteLanes(SAMPLE_VALUE(a, s));
    FOR_EACH_ATTACHMENT(OR_NON_FINITE_VALUE)
    usable[s] = all(equal(nonFinite, uvec4(0u)));
    distance[s] = SAMPLE_DISTANCE(s);
    sortKey[s] = fso && isinf(distance[s]) ? 0.0 : distance[s];
    if (usable[s]) ++usableCount;
  }
#define CLEAR_VALUE(a) values[a] = vec4(0.0);
  if (usableCount == 0) {  // every sample corrupt: write an empty background pixel
    FOR_EACH_ATTACHMENT(CLEAR_VALUE)
#if DEPTH_SOURCE == DEPTH_SOURCE_POSITION_CHANNEL
    values[POSITION_ATTACHMENT][DEPTH_CHANNEL] = backgroundStoredDepth();
#endif
    depth = kDepthBufferFar;
    return;
  }

  int referenceRank;
  if (RESOLVE_WEIGHTING == WEIGHTING_FRONT || RESOLVE_WEIGHTING == WEIGHTING_MEAN)
    referenceRank = 0;
  else if (RESOLVE_WEIGHTING == WEIGHTING_BACK)
    referenceRank = usableCount - 1;
  else if (fso)  // dists[1] of 4, [3] of 8, [7] of 16 in ascending view z; other counts: front first
    referenceRank = (SAMPLES == 4 || SAMPLES == 8 || SAMPLES == 16) ? usableCount / 2 : 0;
  else if (RESOLVE_WEIGHTING == WEIGHTING_WINDOW)
    referenceRank = usableCount - 1 - (usableCount - 1) / 2;  // the farther middle sample
  else
    referenceRank = (usableCount - 1) / 2;  // a real middle sample: the nearer of two for even N
  int reference = 0, nextInOrder = 0;  // the samples at referenceRank and at the rank after it
  for (int s = 0; s < SAMPLES; ++s) {
    int rank = 0;
    for (int t = 0; t < SAMPLES; ++t)
      if (usable[t] && (sortKey[t] < sortKey[s] || (sortKey[t] == sortKey[s] && t < s))) ++rank;
    if (usable[s] && rank == referenceRank) reference = s;
    if (usable[s] && rank == referenceRank + 1) nextInOrder = s;
  }
  float dRef = 0.0, dNext = 0.0;
  for (int s = 0; s < SAMPLES; ++s) {
    if (s == reference) dRef = distance[s];
    if (s == nextInOrder) dNext = distance[s];
  }
  // The median of an even count split evenly between two surfaces: each half within Eq. 1 of its middle.
  bool evenSplit = false;
  if (uSplitByNeighbours && RESOLVE_WEIGHTING == WEIGHTING_MEDIAN && usableCount % 2 == 0 && !isinf(dRef)) {
    int nearHalf = 0, farHalf = 0;
    for (int s = 0; s < SAMPLES; ++s)
      if (usable[s]) {
        if (abs(distance[s] - dRef) <= min(distance[s], dRef) * uFootprintTan * uCloseness) ++nearHalf;
        if (isinf(dNext) ? isinf(distance[s])
                         : abs(distance[s] - dNext) <= min(distance[s], dNext) * uFootprintTan * uCloseness)
          ++farHalf;
      }
    evenSplit = nearHalf == usableCount / 2 && farHalf == usableCount / 2;
  }
  if (fartherSurfaceCoversMore(pixel, dRef, dNext, evenSplit ? 8 * SAMPLES : 0)) {
    reference = nextInOrder;
    dRef = dNext;
  }
  // The reference's depth-buffer value, which both paths below write for a surface: chosen by the loop
  // counter where the samples are kept (an index from data would put the array in memory).
#if SAMPLES <= 8
  float referenceDepthBuffer = 0.0;
  for (int s = 0; s < SAMPLES; ++s)
    if (s == reference) referenceDepthBuffer = fetchedDepthBuffer[s];
#else
  float referenceDepthBuffer = FETCH(uDepthBuffer, pixel, reference).r;
#endif
#if SAMPLES <= 8
  // One surface: every sample bit-identical in every attachment (one primitive's outputs; a NaN compares
  // unequal, so corrupt samples take the general path). The weighted mean of equal values is the value:
  // sample 0 passes through, its normal re-encoded as the mean's would be, with the depth the general path
  // writes (the reference's; the farthest for background). FSO's weighting averages depths: not here.
  // Written for every pixel in straight-line code; the general path below replaces it where it runs.
  bool identical = usableCount == SAMPLES && !fso;
  for (int s = 1; s < SAMPLES; ++s)
#define SAME_AS_FIRST(a) identical = identical && all(equal(fetched[s][a], fetched[0][a]));
    FOR_EACH_ATTACHMENT(SAME_AS_FIRST)
#define FIRST_SAMPLE(a) values[a] = fetched[0][a];
  FOR_EACH_ATTACHMENT(FIRST_SAMPLE)
  depth = referenceDepthBuffer;
  if (isinf(dRef)) {
    depth = 0.0;
    for (int s = 0; s < SAMPLES; ++s) depth = max(depth, fetchedDepthBuffer[s]);
  }
#if NORMAL_ATTACHMENT >= 0
  else {
    vec3 n = decodeNormal(values[NORMAL_ATTACHMENT]);
    if (!(length(n) > 1e-4)) n = vec3(0.0, 0.0, 1.0);
    values[NORMAL_ATTACHMENT] = encodeNormal(values[NORMAL_ATTACHMENT], normalize(n));
  }
#endif
#else
  bool identical = false;
#endif

  // Every other pixel: samples of more than one surface, or corrupt ones. No loop here holds a `continue`,
  // `break` or `return`: such a loop is not unrolled before the arrays are placed, every array it indexes
  // then lives in memory (llvmpipe: the whole resolve 1.3x slower for two of them).
  if (!identical) {
    float referenceViewZ = isinf(dRef) ? 0.0 : -dRef;
    bool referenceIsBackground = fso ? referenceViewZ >= -0.001 : isinf(dRef);

    float weight[SAMPLES];
    float weightSum = 0.0;
    int contributors = 0, lastContributor = reference;
    for (int s = 0; s < SAMPLES; ++s) {
      float w = 0.0;
      if (usable[s]) {
        bool background = isinf(distance[s]);
        if (fso) {
          w = fsoWeight(referenceViewZ, background ? 0.0 : -distance[s]);
        } else if (referenceIsBackground || background) {
          w = (referenceIsBackground && background) ? 1.0 : 0.0;
        } else if (RESOLVE_WEIGHTING == WEIGHTING_MEAN) {
          w = 1.0;
        } else if (RESOLVE_WEIGHTING == WEIGHTING_WINDOW) {
          float footprint = dRef * uFootprintTan;
          w = smoothRamp(dRef - kWindowEnd * footprint, dRef - kWindowFull * footprint, distance[s]) *
              smoothRamp(dRef + kWindowEnd * footprint, dRef + kWindowFull * footprint, distance[s]);
        } else {
          w = abs(distance[s] - dRef) <= min(distance[s], dRef) * uFootprintTan * uCloseness ? 1.0 : 0.0;
        }
        if (s == reference && !fso) w = 1.0;  // ours always count the reference (c = 0 keeps only its depth)
      }
      weight[s] = w;
      weightSum += w;
      if (w > 0.0) ++contributors, lastContributor = s;
    }

    if (contributors == 1) {  // one sample: pass it through untouched (N = 1 equals `off` bit for bit)
      bool markedBackground = false;
      for (int s = 0; s < SAMPLES; ++s)
        if (s == lastContributor) {
#define CONTRIBUTOR_VALUE(a) values[a] = SAMPLE_VALUE(a, s);
          FOR_EACH_ATTACHMENT(CONTRIBUTOR_VALUE)
          markedBackground = SAMPLE_MARKED_BACKGROUND(s);
          depth = SAMPLE_DEPTH_BUFFER(s);
        }
#if NORMAL_ATTACHMENT >= 0
      values[NORMAL_ATTACHMENT] = safeNormal(values[NORMAL_ATTACHMENT], markedBackground);
#endif
    } else {
      float depthSum = 0.0;
      float depthBufferMean = 0.0, depthBufferMax = 0.0;
      vec3 normal = vec3(0.0);  // the weighted mean of the decoded normals
      FOR_EACH_ATTACHMENT(CLEAR_VALUE)
      for (int s = 0; s < SAMPLES; ++s) {
        float w = weight[s] / weightSum;
        if (w > 0.0) {
#define ADD_WEIGHTED(a) values[a] += w * SAMPLE_VALUE(a, s);
          FOR_EACH_ATTACHMENT(ADD_WEIGHTED)
#if NORMAL_ATTACHMENT >= 0
          normal += w * decodeNormal(SAMPLE_VALUE(NORMAL_ATTACHMENT, s));
#endif
          if (!referenceIsBackground) depthSum += w * distance[s];
          depthBufferMean += w * SAMPLE_DEPTH_BUFFER(s);
          depthBufferMax = max(depthBufferMax, SAMPLE_DEPTH_BUFFER(s));
        }
      }

      // Depth is averaged in metres and re-encoded: no encoding but `linear` is linear.
#if DEPTH_SOURCE == DEPTH_SOURCE_POSITION_CHANNEL
      if (!referenceIsBackground) values[POSITION_ATTACHMENT][DEPTH_CHANNEL] = encodeDepth(depthSum);
#endif
#if NORMAL_ATTACHMENT >= 0
      float len = length(normal);
      if (!(len > 1e-4)) {  // opposing or zero-length normals: fall back to the reference's, then the view
        for (int s = 0; s < SAMPLES; ++s)
          if (s == reference) normal = decodeNormal(SAMPLE_VALUE(NORMAL_ATTACHMENT, s));
        len = length(normal);
        if (!(len > 1e-4)) normal = vec3(0.0, 0.0, 1.0), len = 1.0;
      }
      // A background pixel keeps its averaged raw values (an octahedral pair averaged as stored).
      if (!referenceIsBackground) values[NORMAL_ATTACHMENT] = encodeNormal(values[NORMAL_ATTACHMENT], normal / len);
#endif
      // FSO writes the weighted mean of the samples' depth-buffer values. Ours write the reference sample's
      // (encoding-agnostic; the farthest for background), so that forward passes after lighting
      // depth-test against the very surface that was lit.
      depth = fso ? depthBufferMean : referenceIsBackground ? depthBufferMax : referenceDepthBuffer;
    }
  }
}
