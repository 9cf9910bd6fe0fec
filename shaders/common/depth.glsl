// The host's view-depth encoding, as its GBufferLayout describes it (retroaa::DepthEncoding).
// DEPTH_ENCODING: 0 linear (stored = d), 1 log above knee.
uniform float uDepthKnee;
uniform float uBackgroundAbove;

float decodeDepth(float stored) {
#if DEPTH_ENCODING == 1
  return stored <= uDepthKnee ? stored : uDepthKnee * exp2(stored / uDepthKnee - 1.0);
#else
  return stored;
#endif
}
float encodeDepth(float d) {
#if DEPTH_ENCODING == 1
  return d <= uDepthKnee ? d : uDepthKnee * (1.0 + log2(d / uDepthKnee));
#else
  return d;
#endif
}
// NaN compares false, so a NaN depth reads as background rather than as geometry.
bool isBackground(float stored) { return !(stored < uBackgroundAbove); }
bool isFiniteValue(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }
