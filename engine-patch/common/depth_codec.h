// The host's view-depth encoding for its FP16 position attachment (z channel).
//
// FP16 tops out at 65504, but space scenes put ships at up to 1e6 m. The encoding is the identity up
// to a knee (8192 m), where FP16 already keeps a relative precision of 2^-11, and logarithmic above
// it: stored = knee * (1 + log2(d / knee)). It is continuous and monotonic, so comparisons of stored
// values order depths correctly, and it maps 1e6 m to 64 979, below FP16's maximum. The relative
// error after an FP16 round trip stays under 5e-4 below the knee and under 1.4e-3 above it (tested).
// Background pixels hold kBackgroundMarker (FP16's maximum), which no depth encodes to.
// The same formula is in shaders/depth_codec.glsl, and the host describes it to the plugin by its
// knee (retroaa::DepthEncoding) so that the plugin compares depths in metres.
#pragma once

#include <cmath>

namespace host::depth_codec {

constexpr float kKnee = 8192.0f;                  // metres; identity below
constexpr float kMaxDepth = 1.0e6f;               // metres; deeper geometry is clamped
constexpr float kBackgroundMarker = 65504.0f;     // FP16 max: "no geometry here"
constexpr float kBackgroundThreshold = 65280.0f;  // stored values above this are background

inline float encode(float depthMetres) {
  const float d = std::fmin(std::fmax(depthMetres, 0.0f), kMaxDepth);
  return d <= kKnee ? d : kKnee * (1.0f + std::log2(d / kKnee));
}

inline float decode(float stored) { return stored <= kKnee ? stored : kKnee * std::exp2(stored / kKnee - 1.0f); }

inline bool isBackground(float stored) { return !(stored < kBackgroundThreshold); }

}  // namespace host::depth_codec

// FreeSpace Open's current position z (z-compress.sdr, FSO PR #7245): the host stores this instead when
// a scene asks for "position_depth": "fso-compressed". View z (negative in front) maps piecewise onto
// FP16: ×0.01 below 10 m, then scale·2^((linear − offset)·rate) segments up to 100, 1570, 3000,
// 10 000, 100 000 m and GLOBAL_FAR_Z (FSO's far plane, which maps to −65 000). Background is 0.
// The same formulas are in shaders/depth_codec.glsl.
namespace host::fso_z {

struct Segment {
  float scale, rate, offset;
};

inline Segment farSegment(float globalFarZ) {
  return {-1000.0f, std::log2(1000.0f / 65000.0f) / (100000.0f - globalFarZ), 100000.0f};
}

inline float compress(float viewZ, float globalFarZ) {
  const float linear = std::fmax(-viewZ, 0.0f);
  if (linear < 10.0f) return linear * 0.01f;
  Segment s = farSegment(globalFarZ);
  if (linear < 100.0f)
    s = {0.05550473078f, 0.08493173544f, 0.0f};
  else if (linear < 1570.0f)
    s = {11.53589613947f, 0.00793869919f, 0.0f};
  else if (linear < 3000.0f)
    s = {-0.1f, 0.00928910863f, 3000.0f};
  else if (linear < 10000.0f)
    s = {-0.1f, 0.00094912231f, 3000.0f};
  else if (linear < 100000.0f)
    s = {-6.98947320727f, 0.00007382062f, 3000.0f};
  return s.scale * std::exp2((linear - s.offset) * s.rate);
}

inline float uncompress(float compressed, float globalFarZ) {
  Segment s{};
  if (compressed < -1000.0f)
    s = farSegment(globalFarZ);
  else if (compressed < -10.0f)
    s = {-6.98947320727f, 0.00007382062f, 3000.0f};
  else if (compressed < -0.1f)
    s = {-0.1f, 0.00094912231f, 3000.0f};
  else if (compressed < 0.0f)
    s = {-0.1f, 0.00928910863f, 3000.0f};
  else if (compressed < 0.1f)
    return compressed * -100.0f;
  else if (compressed < 20.0f)
    s = {0.05550473078f, 0.08493173544f, 0.0f};
  else
    s = {11.53589613947f, 0.00793869919f, 0.0f};
  return -(std::log2(compressed / s.scale) / s.rate + s.offset);
}

// FSO's resolve and lighting treat view z ≥ −0.001 (within 1 mm of the eye) as no geometry.
inline bool isBackground(float compressed, float globalFarZ) { return !(uncompress(compressed, globalFarZ) < -0.001f); }

}  // namespace host::fso_z
