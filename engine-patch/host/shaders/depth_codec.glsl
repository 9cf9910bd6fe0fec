// View-depth encoding of the position attachment's z channel; see depth_codec.h for the derivation.
const float kDepthKnee = 8192.0;
const float kMaxDepth = 1.0e6;
const float kBackgroundMarker = 65504.0;
const float kBackgroundThreshold = 65280.0;

float encodeDepth(float d) {
  d = clamp(d, 0.0, kMaxDepth);
  return d <= kDepthKnee ? d : kDepthKnee * (1.0 + log2(d / kDepthKnee));
}
float decodeDepth(float stored) {
  return stored <= kDepthKnee ? stored : kDepthKnee * exp2(stored / kDepthKnee - 1.0);
}
bool isBackgroundDepth(float stored) { return !(stored < kBackgroundThreshold); }
