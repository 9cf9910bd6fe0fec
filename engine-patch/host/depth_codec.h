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

constexpr float kKnee = 8192.0f;             // metres; identity below
constexpr float kMaxDepth = 1.0e6f;          // metres; deeper geometry is clamped
constexpr float kBackgroundMarker = 65504.0f;  // FP16 max: "no geometry here"
constexpr float kBackgroundThreshold = 65280.0f;  // stored values above this are background

inline float encode(float depthMetres) {
  const float d = std::fmin(std::fmax(depthMetres, 0.0f), kMaxDepth);
  return d <= kKnee ? d : kKnee * (1.0f + std::log2(d / kKnee));
}

inline float decode(float stored) {
  return stored <= kKnee ? stored : kKnee * std::exp2(stored / kKnee - 1.0f);
}

inline bool isBackground(float stored) { return !(stored < kBackgroundThreshold); }

}  // namespace host::depth_codec
