#version 450 core
// `temporal`: one frame of temporal accumulation (Karis, "High Quality Temporal Supersampling", 2014;
// Salvi's variance clipping, 2016). The host rendered this frame with its projection shifted by the
// plugin's jitter; each pixel finds where its surface was in the previous frame (view depth and the two
// frames' matrices), fetches the history there (Lanczos-2), clips it to the box of this frame's 3×3
// neighbourhood in YCoCg, rejects it where the surface was hidden (depth) or off screen, and blends.
// Writes the pixel (location 0) and the new history (location 1: linear colour, view depth in w).
//
// Defines: LINEAR_INPUT (the display is read through its sRGB view, which the texture unit decodes, so
// the output is encoded again), DISPLAY_HOLDS_LINEAR (common/display_encoding.glsl), HAS_VELOCITY (the layout's velocity attachment: geometry follows it
// instead of the camera, so objects that move on their own keep their history), MAX_MOVING_OBJECTS and
// the depth buffer's encoding. The history always holds linear colour.
#include "common/depth_buffer.glsl"
#include "common/display_encoding.glsl"

layout(binding = 0) uniform sampler2D uInput;    // a copy of this frame (display or light target)
layout(binding = 1) uniform sampler2D uHistory;  // the previous output; w the view depth (m), -1 sky
layout(binding = 2) uniform sampler2D uDepth;    // the host's single-sample depth buffer
layout(binding = 3) uniform sampler2D uVelocity;  // HAS_VELOCITY: the host's screen motion (px, this − previous)

uniform mat4 uViewToPreviousClip;  // previous projection × previous view × inverse(this view)
uniform vec4 uProjection;          // P[0][0], P[1][1], P[2][0], P[2][1] of this frame's unjittered projection
uniform float uClipWPerViewZ;      // P[2][3]: -1 for GL's right-handed view space, +1 for a left-handed one
uniform float uBlend;              // the current frame's weight
uniform float uHistoryValid;       // 0 on the first frame after a reset (cut, new config, no matrices)
uniform vec2 uSampleOffset;        // where this frame's samples lie from their pixels' centres (px): the jitter
// FrameInfo::movingObjects, nearest first: a surface inside box i (this view to [-1, 1]³) reprojects
// through the object's own motion instead of the camera's alone.
uniform int uMovingObjects;
uniform mat4 uViewToBox[MAX_MOVING_OBJECTS];
uniform mat4 uObjectViewToPreviousClip[MAX_MOVING_OBJECTS];

// Pixels whose light, history or blend was not finite (NaN, infinite): the plugin reads the count
// frames later and tells the host once.
layout(binding = 0, offset = 0) uniform atomic_uint uNonFinite;
// Pixels whose history is shorter than the jitter sequence (their blend weight at least
// uShortHistoryBlend, or their history rejected), on frames that continue a history: the plugin sets the
// mip bias by their share.
layout(binding = 0, offset = 4) uniform atomic_uint uShortHistory;
uniform float uShortHistoryBlend;

layout(location = 0) out vec4 outColour;
layout(location = 1) out vec4 outHistory;

const float kSkyDepth = -1.0;
const float kNoHistory = -2.0;  // history w: the texel holds no history (its pixel was not finite)
const float kDepthSlack = 0.01;  // relative: history depth within the footprint's range ± 1 % matches
// The clip box: mean ± γσ of the neighbourhood (Salvi), within its min-max box. γ = 1 where the
// history moved a quarter pixel or more; wider for a still one, whose reprojection is exact and whose
// jittered neighbourhood misses sub-pixel detail the history holds (a tight box would cut it every frame).
// (γ = 2 still: on the demo frame every wider box measured the same, and 1 lost 0.2-0.3 dB.)
const float kStillClipGamma = 2.0, kMovingClipGamma = 1.0;
// Motion (px a frame) from which a moving history gets its tight box and its highest blend. Low, because
// what blurs a moving history is how often it is resampled, not how far it moves: the recorded paths
// played at 2x and 4x their frame rate and measured at the same moments lost up to 3.0 dB interior with
// ramps over 1 and 2 px; with these, at most 0.8 (retroaa regress; docs/methods/temporal.md).
const float kMotionForTightClip = 0.25, kMotionForFullBlend = 0.5;

// This frame's input as linear light, and the output as the target stores it. LINEAR_INPUT: the display's
// sRGB view, which the texture unit decodes, and a target written without GL_FRAMEBUFFER_SRGB. Otherwise
// as common/display_encoding.glsl says (before the tonemap the plugin defines DISPLAY_HOLDS_LINEAR: light).
#if LINEAR_INPUT
vec3 inputToLinear(vec3 c) { return c; }
vec3 encode(vec3 c) { return srgbEncode(c); }
#else
vec3 inputToLinear(vec3 c) { return displayToLinear(c); }
vec3 encode(vec3 c) { return linearToDisplay(c); }
#endif

vec3 toYCoCg(vec3 c) {
  return vec3(dot(c, vec3(0.25, 0.5, 0.25)), dot(c, vec3(0.5, 0.0, -0.5)), dot(c, vec3(-0.25, 0.5, -0.25)));
}
vec3 fromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

bool finite3(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

// Karis's range compression, c / (1 + luma), for the clip alone: a bright sub-pixel highlight (a star)
// would otherwise stretch its neighbours' boxes over the halo a resampled history spreads around it.
// The blend stays in radiance, which the ground truth averages (compressing it too cost 0.3 dB on a
// still frame; clipping compressed gained 0.1-0.4 dB interior on every recorded path, retroaa regress).
float lumaOf(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
vec3 compress(vec3 c) { return c / (1.0 + lumaOf(c)); }
vec3 expand(vec3 c) { return c / max(1.0 - lumaOf(c), 1e-4); }

// Lanczos-2 over the 4×4 texels around `uv`, its ringing clamped to the range of the 2×2 nearest (FSR 2's
// history fetch). Sharper than the 5-tap Catmull-Rom it replaced, which a moving history went through
// every frame: on the recorded paths up to +0.7 dB interior (fence -0.05), the flicker lower on four of
// five (retroaa regress). A still history is fetched at its texel centres, as the texel itself (main).
float lanczos2(float x) {
  x = abs(x);
  if (x < 1e-5) return 1.0;
  if (x >= 2.0) return 0.0;
  float px = 3.14159265 * x;
  return 2.0 * sin(px) * sin(0.5 * px) / (px * px);
}
// `fromInput`: the image is uInput, read as linear light (inputToLinear); the history is stored so.
// `wanted`: false where the pixel does not use it (it returns 0 there). A branch costs llvmpipe both of
// its sides under a mask, so a fetch inside an `if` costs every pixel; a loop over rows counted from
// `wanted` is skipped by a group of pixels none of which wants it (the resolve's even split does the same).
vec3 lanczos(sampler2D image, vec2 uv, bool fromInput, bool wanted) {
  ivec2 size = textureSize(image, 0);
  vec2 position = uv * vec2(size) - 0.5;  // in texel centres
  ivec2 first = ivec2(floor(position)) - 1;
  vec2 f = position - floor(position);
  vec3 sum = vec3(0.0), nearestLow = vec3(1e30), nearestHigh = vec3(-1e30);
  float weight = 0.0;
  float wx[4];  // the kernel is separable
  int rows = wanted ? 4 : 0;
  for (int x = 0; x < rows; ++x) wx[x] = lanczos2(float(x - 1) - f.x);
  for (int y = 0; y < rows; ++y) {
    float wy = lanczos2(float(y - 1) - f.y);
    for (int x = 0; x < 4; ++x) {
      vec3 c = texelFetch(image, clamp(first + ivec2(x, y), ivec2(0), size - 1), 0).rgb;
      if (fromInput) c = inputToLinear(c);
      float w = wx[x] * wy;
      sum += c * w;
      weight += w;
      if (x >= 1 && x <= 2 && y >= 1 && y <= 2) {
        nearestLow = min(nearestLow, c);
        nearestHigh = max(nearestHigh, c);
      }
    }
  }
  return wanted ? clamp(sum / weight, nearestLow, nearestHigh) : vec3(0.0);
}

// Where the history is not the same surface: no texel of the 3×3 footprint around `uv`'s nearest holds a
// depth near `expected` (the sky matches only the sky). 3×3, not the bilinear 2×2: a silhouette pixel's
// jittered samples see the surface in front in some frames and the one behind in others, and its
// history's depth may be either. (Testing against the range the pixel's 3×3 neighbourhood sees instead
// kept more of a race's corn and wires, +0.3 dB, but let the old surface's history into the first column
// of every disocclusion: a ghost one pixel wide.)
bool disoccluded(vec2 uv, float expected) {
  ivec2 size = textureSize(uHistory, 0);
  ivec2 nearest = ivec2(floor(uv * vec2(size)));
  float restarted = 0.5 * (kSkyDepth + kNoHistory);  // below: a texel that holds no history
  float low = 1e30, high = -1e30;
  bool sky = false, geometry = false;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      float depth = texelFetch(uHistory, clamp(nearest + ivec2(x, y), ivec2(0), size - 1), 0).w;
      if (depth < restarted) {  // neither a surface nor the sky; at the nearest, a history restarting
        if (x == 0 && y == 0) return true;
        continue;
      }
      if (depth < 0.0) {
        sky = true;
      } else {
        geometry = true;
        low = min(low, depth);
        high = max(high, depth);
      }
    }
  if (expected < 0.0) return !sky;
  return !geometry || expected < low * (1.0 - kDepthSlack) || expected > high * (1.0 + kDepthSlack);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uInput, 0) - 1;
  // This frame's 3×3 neighbourhood: the clip box's moments.
  vec3 current = inputToLinear(texelFetch(uInput, pixel, 0).rgb);
  vec3 mean = vec3(0.0), squares = vec3(0.0), lowest = vec3(1e30), highest = vec3(-1e30);
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      vec3 c = toYCoCg(compress(max(inputToLinear(texelFetch(uInput, clamp(pixel + ivec2(x, y), ivec2(0), last), 0).rgb), vec3(0.0))));
      mean += c;
      squares += c * c;
      lowest = min(lowest, c);
      highest = max(highest, c);
    }
  // Where this pixel's surface was a frame ago. The history holds unjittered pixel centres: the point
  // under this pixel's centre (at the depth its jittered sample saw) is reprojected, so a still camera
  // reads the history where it writes it and never resamples it; this frame's sample, off the centre by
  // the jitter, is blended in there, and over the sequence the pixel averages its whole area. The sky
  // reprojects as a direction.
  float z = texelFetch(uDepth, pixel, 0).r;
  bool sky = depthBufferIsFar(z);
  float depth = sky ? kSkyDepth : depthBufferToMetres(z);
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(last + 1) * 2.0 - 1.0;
  // View-space x/d and y/d for any perspective projection: clip w = P[2][3]·z = d, so z = d / P[2][3],
  // and ndc.x = (P[0][0]·x + P[2][0]·z) / d.
  vec2 ray = (ndc - uProjection.zw / uClipWPerViewZ) / uProjection.xy;
  float zPerDepth = 1.0 / uClipWPerViewZ;
  vec4 viewPoint = sky ? vec4(ray, zPerDepth, 0.0) : vec4(ray * depth, zPerDepth * depth, 1.0);
  vec4 previousClip = uViewToPreviousClip * viewPoint;
  for (int i = 0; i < uMovingObjects && !sky; ++i)
    if (all(lessThanEqual(abs((uViewToBox[i] * viewPoint).xyz), vec3(1.0)))) {
      previousClip = uObjectViewToPreviousClip[i] * viewPoint;
      break;
    }
  vec2 previousUv = previousClip.xy / previousClip.w * 0.5 + 0.5;
#if HAS_VELOCITY
  // The host's own motion, for geometry (the sky keeps the camera's: no model pass drew it). The depth
  // test below still expects the camera's depth: an object that moves across the view keeps its own.
  if (!sky) previousUv = (vec2(pixel) + 0.5 - texelFetch(uVelocity, pixel, 0).xy) / vec2(last + 1);
#endif
  // A perspective projection's clip w is the view depth.
  float expectedDepth = sky ? kSkyDepth : previousClip.w;

  mean /= 9.0;
  vec3 sigma = sqrt(max(squares / 9.0 - mean * mean, vec3(0.0)));
  float motion = length((previousUv - (vec2(pixel) + 0.5) / vec2(last + 1)) * vec2(last + 1));
  float gamma = mix(kStillClipGamma, kMovingClipGamma, clamp(motion / kMotionForTightClip, 0.0, 1.0));
  vec3 boxLow = max(lowest, mean - gamma * sigma), boxHigh = min(highest, mean + gamma * sigma);

  // This frame at its pixels' centres, resampled from its jittered samples (Karis): what a pixel shows where
  // its history is gone, and half of what it blends in where it moves. As sampled, with the weight it has
  // there, it shifts those pixels by the jitter each frame: in STK's driven race 0.8 dB lower, and the
  // PSNR swinging 1.6 dB with the jitter's phase against 0.75 (retroaa score, docs/results.md).
  // Resampled only where it is used: a still pixel's neighbours then cost nothing and cannot spread a
  // non-finite light into it. A new history, or none kept (blend 1), starts from or shows the frame as
  // rendered.
  vec2 centreUv = (vec2(pixel) + 0.5 - uSampleOffset) / vec2(last + 1);
  bool accumulating = uHistoryValid > 0.5 && uBlend < 1.0;
  vec3 result = current;
  bool currentFinite = finite3(current);
  bool finite = currentFinite;  // false: this pixel shows what it can and its history restarts
  bool usable = uHistoryValid > 0.5 && previousClip.w > 0.0 && all(greaterThanEqual(previousUv, vec2(0.0))) &&
                all(lessThanEqual(previousUv, vec2(1.0))) && !disoccluded(previousUv, expectedDepth);
  if (uHistoryValid > 0.5 && !usable) atomicCounterIncrement(uShortHistory);
  // Still, the frame as sampled (the jitter is how the history gathers the pixel's area); moving, half
  // centred: centring moves edges back where they are, but resampling blurs texture. Against the frame
  // as sampled, on the space-battle and engine paths (retroaa regress): fully centred +1.5 and +2.0 dB
  // edge, -2.7 and -0.4 interior; half +1.3 and +1.7 edge, -1.4 and -0.2 interior; in STK's race half
  // or full alike (edge 24.3, 24.5 against 23.8).
  float centring = 0.5 * clamp(motion / kMotionForFullBlend, 0.0, 1.0);
  // (A still view reprojects to within rounding of the pixel: no resampling below a hundredth of a pixel.)
  bool centres = accumulating && (!usable || centring > 0.01);
  vec3 centred = lanczos(uInput, centreUv, true, centres);
  if (!usable && accumulating) result = centred;
  // Likewise a history within a hundredth of a pixel of its texel's centre is that texel: 16 fetches
  // fewer (a still demo frame's pass 9.4-11.5 → 7.4-8.3 ms on llvmpipe), within 1/255 of the Lanczos sum.
  vec2 historyTexel = previousUv * vec2(last + 1);
  bool onTexel = all(lessThan(abs(fract(historyTexel) - 0.5), vec2(0.01)));
  vec3 history = onTexel ? texelFetch(uHistory, clamp(ivec2(historyTexel), ivec2(0), last), 0).rgb
                         : lanczos(uHistory, previousUv, false, usable && !onTexel);
  if (usable) {
    if (finite3(history)) {
      // Clip towards the box's centre (Salvi), not per channel: keeps the history's hue.
      vec3 h = toYCoCg(compress(history));
      // A flat neighbourhood has a box of no extent: a floor of 1 % of its luma keeps the history's
      // storage rounding (half floats) from counting as far outside it.
      vec3 centre = 0.5 * (boxLow + boxHigh);
      vec3 extent = max(0.5 * (boxHigh - boxLow), vec3(0.01 * abs(centre.x) + 1e-4));
      vec3 toHistory = h - centre;
      vec3 units = abs(toHistory / extent);
      float outside = max(units.x, max(units.y, units.z));
      if (outside > 1.0) h = centre + toHistory / outside;
      // A history fetched between its texels has been resampled (blurred a little); the more so, the more
      // this frame weighs, up to 0.3 (fence and engine paths: +0.3-0.6 dB interior, +0.2 dB edge). A
      // moving one is resampled every frame, its blur compounding: 0.5 from half a pixel a frame.
      vec2 offCentre = abs(fract(previousUv * vec2(last + 1)) - 0.5);  // 0 on a texel's centre
      float resampled = 2.0 * max(offCentre.x, offCentre.y);
      float blend = max(mix(uBlend, max(uBlend, 0.3), resampled), mix(uBlend, 0.5, clamp(motion / kMotionForFullBlend, 0.0, 1.0)));
      if (blend >= uShortHistoryBlend) atomicCounterIncrement(uShortHistory);
      // Moving, each side also weighs 1 / (1 + luma) (Karis): a bright history the clip let through (the
      // halo a resampled star leaves around itself) fades faster. Still, the plain blend, which converges
      // to the pixel's mean (this weighting biases it dark: -0.4 dB edge on the demo frame). Recorded
      // paths: +0.1-0.6 dB interior, flicker down on all five, the still frame unchanged.
      vec3 clipped = expand(fromYCoCg(h));
      vec3 arriving = centres ? mix(current, centred, centring) : current;
      float weighting = clamp(motion, 0.0, 1.0);
      float currentWeight = blend / (1.0 + weighting * lumaOf(arriving));
      float historyWeight = (1.0 - blend) / (1.0 + weighting * lumaOf(clipped));
      result = (arriving * currentWeight + clipped * historyWeight) / (currentWeight + historyWeight);
    } else {
      finite = false;
    }
  }
  if (!finite3(result)) {
    result = currentFinite ? current : vec3(0.0);
    finite = false;
  }
  if (!finite) atomicCounterIncrement(uNonFinite);
  outColour = vec4(encode(result), texelFetch(uInput, pixel, 0).a);
  outHistory = vec4(result, finite ? depth : kNoHistory);
}
