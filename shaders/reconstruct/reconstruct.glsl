// Sub-pixel reconstruction after Chajdas, McGuire and Luebke ("Subpixel Reconstruction Antialiasing",
// I3D 2011), as a retrofit on the tonemapped image. The image was shaded once per pixel; the
// multisampled depth and normals say what each sub-sample sees. A sub-sample on its own pixel's surface
// (depth within Eq. 1 of the pixel's, normals agreeing) keeps the pixel's colour, so interiors and their
// texture detail pass through bit for bit. Any other sub-sample takes the colour of the neighbouring
// shaded pixels whose geometry matches it, weighted by that match and by how near their centres lie
// to the sub-sample: the silhouette pixel becomes the coverage-weighted mix of the surfaces it holds.
// A sub-sample no neighbour matches that lies in front of or behind everything around it (a wire or a
// gap thinner than a pixel) searches farther rings: a pixel centre hits the same wire a few pixels along
// it. One that no pixel within SEARCH_RADIUS matches cannot be rebuilt and keeps the pixel's colour.
// Colours are mixed in linear light (the display holds sRGB-encoded values): averaging the encoded
// values darkens every blended edge, 0.8 dB of edge PSNR on the demo.
// The plugin prepends SAMPLES, DEPTH_BUFFER_ENCODING, NORMAL_ENCODING, HAS_NORMALS, PACKED_SAMPLE_NORMALS,
// SEARCH_RADIUS (rings of pixels, 1: the 3×3 neighbourhood), RADIANCE (run on the HDR light target
// before tonemapping instead of on the display), LINEAR_INPUT (the display arrives decoded to linear),
// DISPLAY_HOLDS_LINEAR (common/display_encoding.glsl) and FORWARD_MASK (the host
// draws forward passes: a pixel they drew keeps its colour and lends it to no sub-sample, since the depth
// and normals here are the opaque surfaces' alone).
// reconstruct.frag runs it as a full-screen pass in place, reconstruct.comp (`reconstruct_compute=on`)
// as a compute pass that packs each tile's searching pixels onto adjacent invocations.
#include "common/depth_buffer.glsl"
#include "common/normal.glsl"
layout(binding = 0) uniform sampler2D uInput;           // a copy of the display (or of the light target)
layout(binding = 1) uniform sampler2D uPixelDepth;      // the host's single-sample depth buffer
layout(binding = 2) uniform sampler2D uPixelNormal;     // the host's single-sample normal (as encoded)
layout(binding = 3) uniform sampler2DMS uSampleDepth;   // multisampled depth of the same frame
layout(binding = 4) uniform sampler2DMS uSampleNormal;  // its normals (xy only when packed)
#define FORWARD_MASK_BINDING 5
#include "common/forward_mask.glsl"
uniform vec2 uSamplePositions[SAMPLES];
uniform float uFootprintTan;  // tan(hfov / width)
uniform float uTolerance;     // c of the Eq. 1 style depth test

const float kSpatialSigma = 0.75;  // pixels: neighbours nearer the sub-sample weigh more
const int kNearRings = 2;          // how far a sub-sample within its neighbours' depths searches
const float kClearMatch = 0.01;    // similarity below this (normals ~56° apart) only if nothing better
// The depth tolerance beyond ring 1, as a multiple of Eq. 1's. A pixel centre two or more pixels from
// the sub-sample lies on a tilted face (or along a wire receding from the camera) at a depth that grows
// with tan(tilt) × distance: Eq. 1's tolerance (c = 2) holds faces up to 63° at one pixel, this up to
// 86° at two. What searches there is already narrowed by the normals and by lying in or out of its
// neighbours' depths; with no depth test at all a far surface of the same normal stands in (demo
// −0.2 dB, heavy lighting −0.3 dB against this).
const float kFarRingTolerance = 16.0;

#include "common/display_encoding.glsl"
#if RADIANCE  // linear HDR light, written back so
vec3 toLinear(vec3 c) { return c; }
vec3 toDisplay(vec3 c) { return c; }
#elif LINEAR_INPUT  // the display's sRGB view: the texture unit decodes
vec3 toLinear(vec3 c) { return c; }
vec3 toDisplay(vec3 c) { return linearToDisplay(c); }
#else
vec3 toLinear(vec3 c) { return displayToLinear(c); }
vec3 toDisplay(vec3 c) { return linearToDisplay(c); }
#endif

struct Geometry {
  float depth;  // metres
  vec3 normal;
  bool background;
};

vec3 unitOrFacing(vec3 n) { return dot(n, n) > 1e-12 ? normalize(n) : vec3(0.0, 0.0, 1.0); }

// A shaded pixel's depth alone, and then its normal: the search reads the normal only where a
// sub-sample still searching matches the depth.
Geometry pixelDepth(ivec2 pixel) {
  float z = texelFetch(uPixelDepth, pixel, 0).r;
  Geometry g;
  g.background = depthBufferIsFar(z);
  g.depth = depthBufferToMetres(z);
  g.normal = vec3(0.0, 0.0, 1.0);
  return g;
}

Geometry withNormal(Geometry g, ivec2 pixel) {
#if HAS_NORMALS
  g.normal = unitOrFacing(decodeNormal(texelFetch(uPixelNormal, pixel, 0)));
#endif
  return g;
}

Geometry pixelGeometry(ivec2 pixel) { return withNormal(pixelDepth(pixel), pixel); }

Geometry sampleGeometry(ivec2 pixel, int s) {
  float z = texelFetch(uSampleDepth, pixel, s).r;
  Geometry g;
  g.background = depthBufferIsFar(z);
  g.depth = depthBufferToMetres(z);
// The pair encodings name the normal by xy alone; a view-space xyz normal comes as xy too in the prepass
// (PACKED_SAMPLE_NORMALS, z ≥ 0 rebuilt); any other xyz normal comes whole.
#if HAS_NORMALS && (NORMAL_ENCODING == NORMAL_OCTAHEDRAL || NORMAL_ENCODING == NORMAL_SPHEREMAP)
  g.normal = decodeNormal(vec4(texelFetch(uSampleNormal, pixel, s).xy, 0.0, 0.0));
#elif HAS_NORMALS && PACKED_SAMPLE_NORMALS
  vec2 xy = texelFetch(uSampleNormal, pixel, s).xy;
  g.normal = unitOrFacing(vec3(xy, sqrt(max(1.0 - dot(xy, xy), 0.0))));
#elif HAS_NORMALS
  g.normal = unitOrFacing(texelFetch(uSampleNormal, pixel, s).xyz);
#else
  g.normal = vec3(0.0, 0.0, 1.0);
#endif
  return g;
}

// Whether a and b may be one surface by depth alone: both background, or both geometry within
// `tolerance` pixel footprints.
bool sameDepth(Geometry a, Geometry b, float tolerance) {
  if (a.background || b.background) return a.background && b.background;
  return abs(a.depth - b.depth) <= min(a.depth, b.depth) * uFootprintTan * tolerance;
}

// How well two geometries of the same depth agree: cos⁸ of the angle between their normals (0.5 at
// 24°); 1 between background and background.
float normalAgreement(Geometry a, Geometry b) {
  if (a.background) return 1.0;
  float c = max(dot(a.normal, b.normal), 0.0);
  c *= c;
  c *= c;
  return c * c;
}

// How well a shaded pixel stands for a sub-sample: 0 unless sameDepth, normalAgreement otherwise.
float similarity(Geometry a, Geometry b, float tolerance) {
  return sameDepth(a, b, tolerance) ? normalAgreement(a, b) : 0.0;
}

// The depths of a pixel and its eight neighbours; background lies behind every depth.
struct Range {
  float nearest;  // metres, over the geometry among them
  float farthest;
  bool background;  // any of them is background
};

Range widen(Range r, Geometry g) {
  if (g.background) {
    r.background = true;
  } else if (r.nearest > r.farthest) {  // no geometry yet
    r.nearest = r.farthest = g.depth;
  } else {
    r.nearest = min(r.nearest, g.depth);
    r.farthest = max(r.farthest, g.depth);
  }
  return r;
}

// Whether a sub-sample lies in front of or behind everything in the range, beyond the depth tolerance.
bool outside(Geometry g, Range r) {
  bool anyGeometry = r.nearest <= r.farthest;
  if (g.background) return !r.background;
  if (!anyGeometry) return true;
  float tolerance = g.depth * uFootprintTan * uTolerance;
  return g.depth + tolerance < r.nearest || (!r.background && g.depth - tolerance > r.farthest);
}

// The change of 1 / depth (affine in the screen across a plane) from `pixel` to its neighbour `step`
// away and to the one opposite, whichever is smaller and on the pixel's own surface (normals agreeing):
// the side that does not cross an edge. 0 where neither is.
float inverseDepthSlope(ivec2 pixel, Geometry own, ivec2 step) {
  ivec2 last = textureSize(uPixelDepth, 0) - 1;
  float slope = 0.0, smallest = 1e30;
  for (int side = -1; side <= 1; side += 2) {
    ivec2 q = pixel + side * step;
    if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue;
    Geometry neighbour = pixelDepth(q);
    if (neighbour.background) continue;
    float change = float(side) * (1.0 / neighbour.depth - 1.0 / own.depth);
    if (abs(change) >= smallest || normalAgreement(own, withNormal(neighbour, q)) < 0.5) continue;
    smallest = abs(change);
    slope = change;
  }
  return slope;
}

// The sub-samples of `pixel` that do not lie on its own surface (bit s: sub-sample s), with the
// geometry of its shaded centre and of every sub-sample. A sub-sample off the centre's depth but on
// the plane its neighbours continue (a floor seen at a grazing angle, whose depth changes by many
// footprints inside one pixel) is on it: its texture is no edge to rebuild (STK's black_forest, the
// start line's checks smeared: interior 32.8 -> 35.7 dB, `off` 35.4). Within half Eq. 1's tolerance of
// the plane: at the whole, a wire just above a grazing box top joined it (demo -0.2 dB edge; at half,
// -0.03, and resolve+reconstruct's resolved depth, a sample's rather than the centre's, still fits).
int subSamplesOffOwnSurface(ivec2 pixel, out Geometry own, out Geometry samples[SAMPLES]) {
  own = pixelGeometry(pixel);
  int open = 0;
  if (forwardEdge(pixel)) return open;  // what covers it is nothing the sub-samples know
  for (int s = 0; s < SAMPLES; ++s) {
    samples[s] = sampleGeometry(pixel, s);
    if (similarity(samples[s], own, uTolerance) < 0.5) open |= 1 << s;
  }
  if (open == 0 || own.background) return open;
  vec2 slope = vec2(inverseDepthSlope(pixel, own, ivec2(1, 0)), inverseDepthSlope(pixel, own, ivec2(0, 1)));
  for (int s = 0; s < SAMPLES; ++s) {
    float inverse = 1.0 / own.depth + dot(uSamplePositions[s] - 0.5, slope);
    if (((open >> s) & 1) != 0 && !(inverse <= 0.0)) {  // an `if`, not `continue` (docs/architecture.md)
      Geometry onPlane = own;
      onPlane.depth = 1.0 / inverse;
      if (similarity(samples[s], onPlane, 0.5 * uTolerance) >= 0.5) open &= ~(1 << s);
    }
  }
  return open;
}

// Whether every sub-sample of `pixel` lies on its own surface: the pixel keeps its colour.
bool allOnOwnSurface(ivec2 pixel) {
  Geometry own;
  Geometry samples[SAMPLES];
  return subSamplesOffOwnSurface(pixel, own, samples) == 0;
}

// The pixel as the mean of its rebuilt sub-samples, in the input's encoding; `changed` false where
// every sub-sample lies on the pixel's own surface (the result is then undefined: keep the pixel).
vec4 reconstructPixel(ivec2 pixel, out bool changed) {
  ivec2 last = textureSize(uInput, 0) - 1;
  Geometry own;
  Geometry samples[SAMPLES];
  int open = subSamplesOffOwnSurface(pixel, own, samples);  // bit s: sub-sample s still looks for its surface
  changed = open != 0;
  if (!changed) return vec4(0.0);
  vec3 colour[SAMPLES];
  float weightSum[SAMPLES];
  bool underFilm = underForwardFilm(pixel);
  // Only now the pixel's own colour: most pixels never need it.
  vec4 centre = texelFetch(uInput, pixel, 0);
  vec3 centreLinear = toLinear(centre.rgb);
  for (int s = 0; s < SAMPLES; ++s) {
    bool onOwnSurface = ((open >> s) & 1) == 0;
    colour[s] = onOwnSurface ? centreLinear : vec3(0.0);
    weightSum[s] = onOwnSurface ? 1.0 : 0.0;
  }
  // Search outwards ring by ring; each sub-sample stops at the first ring holding its surface. Every
  // ring pixel's depth is fetched once for all sub-samples still open, its normal and colour only
  // where one of them matches that depth (around a wire most ring pixels are background). Only a
  // sub-sample in front of (or behind) everything in its 3×3 neighbourhood searches past the second
  // ring: a wire or a gap thinner than a pixel, whose surface a pixel centre hits a few pixels along
  // it. One that lies between its neighbours' depths (a grazing floor, a crease, a bump) rarely has its
  // surface farther out: letting it search on too made the demo's pass 1.4× as costly for 0.03–0.26 dB
  // (llvmpipe).
  int nearOnly = 0;                                   // bit s: sub-sample s lies within its neighbours' depths
  int clearMatch = 0;                                 // bit s: sub-sample s holds matches of at least kClearMatch
  Range around = widen(Range(1.0, 0.0, false), own);  // nearest > farthest: no geometry yet
  for (int ring = 1; ring <= SEARCH_RADIUS && open != 0; ++ring) {
    float nearest = float(ring) - 0.5;  // no sub-sample lies nearer a ring pixel's centre than this
    float tolerance = ring == 1 ? uTolerance : uTolerance * kFarRingTolerance;
    int found = 0;
    // One loop walks the ring's 8 × ring pixels from its corner at (-ring, -ring): on a SIMD
    // rasteriser a loop over rows and one over columns cost their own control (llvmpipe: 0.95×).
    ivec2 d = ivec2(-ring);
    ivec2 step = ivec2(1, 0);
    for (int i = 0; i < 8 * ring; ++i) {
      ivec2 q = pixel + d;
      d += step;
      if (abs(d.x) == ring && abs(d.y) == ring) step = ivec2(-step.y, step.x);  // a corner: turn
      if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue;
      Geometry candidate = pixelDepth(q);
      if (ring == 1) around = widen(around, candidate);
      int depthMatch = 0;  // bit s: open sub-sample s lies at the candidate's depth
      for (int s = 0; s < SAMPLES; ++s)
        if (((open >> s) & 1) != 0 && sameDepth(samples[s], candidate, tolerance)) depthMatch |= 1 << s;
      if (depthMatch == 0 || !lendsColour(q, underFilm)) continue;  // a forward pass's colour is no surface's
      candidate = withNormal(candidate, q);
      // Read once for every sub-sample that takes it. The per-sample loop below chooses with selects
      // rather than branches: a SIMD rasteriser runs both sides of a branch its lanes disagree on, and
      // a read or `continue` inside the loop cost once per sub-sample (llvmpipe: 8.9 → 7.5 ms a pass).
      vec3 candidateLinear = toLinear(texelFetch(uInput, q, 0).rgb);
      for (int s = 0; s < SAMPLES; ++s) {
        float w = ((depthMatch >> s) & 1) != 0 ? normalAgreement(samples[s], candidate) : 0.0;
        // A faint match (normals nearly perpendicular: the other face of a box edge) stands in only
        // if ring 1 holds nothing clearer and, for a sub-sample between its neighbours' depths,
        // ring 2 neither. A wire's sub-sample takes any match in any ring: around a thin cylinder
        // the normals turn through 180°.
        bool clear = w >= kClearMatch || (ring > 1 && ((nearOnly >> s) & 1) == 0);
        bool holdsClear = ((clearMatch >> s) & 1) != 0;
        bool takes = w > 0.0 && (clear || (ring == 1 && !holdsClear));
        bool firstClear = takes && clear && !holdsClear;  // what a faint match left gives way
        colour[s] = firstClear ? vec3(0.0) : colour[s];
        weightSum[s] = firstClear ? 0.0 : weightSum[s];
        clearMatch |= firstClear ? 1 << s : 0;
        vec2 offset = vec2(pixel) + uSamplePositions[s] - (vec2(q) + 0.5);
        // The Gaussian relative to the ring's nearest distance: within one ring only ratios matter,
        // and far rings would otherwise underflow.
        w = takes ? w * exp(-(dot(offset, offset) - nearest * nearest) / (2.0 * kSpatialSigma * kSpatialSigma)) : 0.0;
        colour[s] += w * candidateLinear;
        weightSum[s] += w;
        found |= takes && clear ? 1 << s : 0;
      }
    }
    if (ring == 1)
      for (int s = 0; s < SAMPLES; ++s)
        if (!outside(samples[s], around))
          nearOnly |= 1 << s;
        else if (weightSum[s] > 0.0)
          found |= 1 << s;  // a wire takes even a faint match
    open &= ~found;
    if (ring == kNearRings) open &= ~nearOnly;
  }
  vec3 sum = vec3(0.0);
  for (int s = 0; s < SAMPLES; ++s) sum += weightSum[s] > 0.0 ? colour[s] / weightSum[s] : centreLinear;
  return vec4(toDisplay(sum / float(SAMPLES)), centre.a);
}
