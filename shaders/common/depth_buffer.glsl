// The host's hardware depth buffer as view depth (retroaa::DepthBufferEncoding, injected as
// DEPTH_BUFFER_ENCODING with the DEPTH_BUFFER_* values), with FrameInfo's near and far planes.
uniform float uDepthNear;
uniform float uDepthFar;

#if DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_REVERSED_PERSPECTIVE || DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_REVERSED_INFINITE
const float kDepthBufferFar = 0.0;  // what a pixel without geometry holds
bool depthBufferIsFar(float z) { return !(z > 0.0); }
#else
const float kDepthBufferFar = 1.0;
bool depthBufferIsFar(float z) { return !(z < 1.0); }
#endif

// Metres in front of the camera.
float depthBufferToMetres(float z) {
#if DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_PERSPECTIVE_CLIP_ZERO_TO_ONE
  z = 2.0 * z - 1.0;  // GL made 0.5 + 0.5 × (clip z / w) of it: back to Perspective's value
#endif
#if DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_LOGARITHMIC
  return uDepthNear * exp2(z * log2(uDepthFar / uDepthNear));
#elif DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_REVERSED_PERSPECTIVE
  return uDepthNear * uDepthFar / (uDepthNear + z * (uDepthFar - uDepthNear));
#elif DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_REVERSED_INFINITE
  return uDepthNear / z;
#else
  return uDepthNear * uDepthFar / (uDepthFar - z * (uDepthFar - uDepthNear));
#endif
}

// The inverse: the window depth of a point `d` metres in front of the camera.
float metresToDepthBuffer(float d) {
#if DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_LOGARITHMIC
  return log2(d / uDepthNear) / log2(uDepthFar / uDepthNear);
#elif DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_REVERSED_PERSPECTIVE
  return uDepthNear * (uDepthFar - d) / (d * (uDepthFar - uDepthNear));
#elif DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_REVERSED_INFINITE
  return uDepthNear / d;
#elif DEPTH_BUFFER_ENCODING == DEPTH_BUFFER_PERSPECTIVE_CLIP_ZERO_TO_ONE
  return 0.5 + 0.5 * uDepthFar * (d - uDepthNear) / (d * (uDepthFar - uDepthNear));
#else
  return uDepthFar * (d - uDepthNear) / (d * (uDepthFar - uDepthNear));
#endif
}
