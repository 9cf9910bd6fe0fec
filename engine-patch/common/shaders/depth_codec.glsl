// View-depth encoding of the position attachment's z channel; see depth_codec.h for the derivation.
// FSO_COMPRESSED_Z (with GLOBAL_FAR_Z): FreeSpace Open's compressed view z instead (z-compress.sdr).
const float kDepthKnee = 8192.0;
const float kMaxDepth = 1.0e6;

#ifdef FSO_COMPRESSED_Z
const float kBackgroundMarker = 0.0;
const float kFarRate = log2(1000.0 / 65000.0) / (100000.0 - GLOBAL_FAR_Z);

float compressViewZ(float viewZ) {
  float linear = max(-viewZ, 0.0);
  if (linear < 10.0) return linear * 0.01;
  vec3 s = vec3(-1000.0, kFarRate, 100000.0);  // scale, rate, offset
  if (linear < 100.0) s = vec3(0.05550473078, 0.08493173544, 0.0);
  else if (linear < 1570.0) s = vec3(11.53589613947, 0.00793869919, 0.0);
  else if (linear < 3000.0) s = vec3(-0.1, 0.00928910863, 3000.0);
  else if (linear < 10000.0) s = vec3(-0.1, 0.00094912231, 3000.0);
  else if (linear < 100000.0) s = vec3(-6.98947320727, 0.00007382062, 3000.0);
  return s.x * exp2((linear - s.z) * s.y);
}
float uncompressViewZ(float c) {
  vec3 s;
  if (c < -1000.0) s = vec3(-1000.0, kFarRate, 100000.0);
  else if (c < -10.0) s = vec3(-6.98947320727, 0.00007382062, 3000.0);
  else if (c < -0.1) s = vec3(-0.1, 0.00094912231, 3000.0);
  else if (c < 0.0) s = vec3(-0.1, 0.00928910863, 3000.0);
  else if (c < 0.1) return c * -100.0;
  else if (c < 20.0) s = vec3(0.05550473078, 0.08493173544, 0.0);
  else s = vec3(11.53589613947, 0.00793869919, 0.0);
  return -(log2(c / s.x) / s.y + s.z);
}
float encodeDepth(float d) { return compressViewZ(-clamp(d, 0.0, kMaxDepth)); }
float decodeDepth(float stored) { return -uncompressViewZ(stored); }
bool isBackgroundDepth(float stored) { return !(uncompressViewZ(stored) < -0.001); }
#else
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
#endif
