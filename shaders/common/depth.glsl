// The host's view-depth encoding, as its GBufferLayout describes it (retroaa::DepthEncoding).
// DEPTH_ENCODING: 0 linear (stored = d), 1 log above knee, 2 FreeSpace Open's compressed view z
// (FSO_GLOBAL_FAR_Z injected with it).
uniform float uDepthKnee;
uniform float uBackgroundAbove;
uniform vec4 uViewDepthRow;  // DepthSource::WorldPosition: the view matrix's third row (view z = row · (p, 1))

#if DEPTH_ENCODING == 2
// FreeSpace Open's z-compress.sdr, written from its definition: view z (negative in front) maps
// piecewise onto one FP16 channel, ×0.01 below 10 m, then exponential segments of the form
// scale·2^((linear − offset)·rate). Near segments are positive, far ones negative.
const float kFsoFarRate = log2(1000.0 / 65000.0) / (100000.0 - FSO_GLOBAL_FAR_Z);

float fsoSegment(float scale, float rate, float offset, float linear) {
  return scale * exp2((linear - offset) * rate);
}
float fsoCompress(float viewZ) {
  float linear = max(-viewZ, 0.0);
  if (linear < 10.0) return linear * 0.01;
  if (linear < 100.0) return fsoSegment(0.05550473078, 0.08493173544, 0.0, linear);
  if (linear < 1570.0) return fsoSegment(11.53589613947, 0.00793869919, 0.0, linear);
  if (linear < 3000.0) return fsoSegment(-0.1, 0.00928910863, 3000.0, linear);
  if (linear < 10000.0) return fsoSegment(-0.1, 0.00094912231, 3000.0, linear);
  if (linear < 100000.0) return fsoSegment(-6.98947320727, 0.00007382062, 3000.0, linear);
  return fsoSegment(-1000.0, kFsoFarRate, 100000.0, linear);
}
// The inverse, branching on the stored value's sign and magnitude as each segment's range dictates.
float fsoUncompress(float c) {
  float scale, rate, offset;
  if (c < -1000.0) scale = -1000.0, rate = kFsoFarRate, offset = 100000.0;
  else if (c < -10.0) scale = -6.98947320727, rate = 0.00007382062, offset = 3000.0;
  else if (c < -0.1) scale = -0.1, rate = 0.00094912231, offset = 3000.0;
  else if (c < 0.0) scale = -0.1, rate = 0.00928910863, offset = 3000.0;
  else if (c < 0.1) return c * -100.0;
  else if (c < 20.0) scale = 0.05550473078, rate = 0.08493173544, offset = 0.0;
  else scale = 11.53589613947, rate = 0.00793869919, offset = 0.0;
  return -(log2(c / scale) / rate + offset);
}
#endif

float decodeDepth(float stored) {
#if DEPTH_ENCODING == 2
  return -fsoUncompress(stored);
#elif DEPTH_ENCODING == 1
  return stored <= uDepthKnee ? stored : uDepthKnee * exp2(stored / uDepthKnee - 1.0);
#else
  return stored;
#endif
}
float encodeDepth(float d) {
#if DEPTH_ENCODING == 2
  return fsoCompress(-d);
#elif DEPTH_ENCODING == 1
  return d <= uDepthKnee ? d : uDepthKnee * (1.0 + log2(d / uDepthKnee));
#else
  return d;
#endif
}
// NaN compares false, so a NaN depth reads as background rather than as geometry.
bool isBackground(float stored) {
#if DEPTH_ENCODING == 2
  return !(decodeDepth(stored) > 0.001);  // FSO's own test: view z >= -0.001
#else
  return !(stored < uBackgroundAbove);
#endif
}
// What a pixel with no geometry holds in the depth channel.
float backgroundStoredDepth() {
#if DEPTH_ENCODING == 2
  return 0.0;
#else
  return uBackgroundAbove;
#endif
}
// Inf and NaN are the floats whose exponent bits are all ones. Tested on the bits and OR-ed over the
// attachments: a chain of `!any(isnan(v)) && !any(isinf(v))` joined by `&&` took 40 % of the resolve's
// time under llvmpipe, the bit test about 10 % (docs/results.md).
uvec4 nonFiniteLanes(vec4 v) { return uvec4(equal(floatBitsToUint(v) & 0x7f800000u, uvec4(0x7f800000u))); }
bool isFiniteValue(vec4 v) { return all(equal(nonFiniteLanes(v), uvec4(0u))); }
