#version 450 core
// The layout check (ResolvePass, once after the G-buffer is made): counted by occlusion queries, no
// colour written. Mode 0 keeps the pixels with no geometry sample under the layout's depth encoding;
// mode 1 the pixels with a geometry sample whose decoded view depth is not positive (a world-space
// position labelled ViewPosition does that: geometry behind the camera's plane; a depth buffer of
// another encoding may too).
#include "common/gbuffer.glsl"
uniform int uMode;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  bool anyGeometry = false, nonPositive = false;
  for (int s = 0; s < SAMPLES; ++s) {
#if DEPTH_SOURCE == DEPTH_SOURCE_DEPTH_BUFFER
    float z = FETCH(uDepthBuffer, pixel, s).r;
    if (depthBufferIsFar(z)) continue;
    anyGeometry = true;
    if (!(depthBufferToMetres(z) > 0.0)) nonPositive = true;
#elif DEPTH_SOURCE == DEPTH_SOURCE_WORLD_POSITION
    if (depthBufferIsFar(FETCH(uDepthBuffer, pixel, s).r)) continue;
    anyGeometry = true;
    if (!(-dot(uViewDepthRow, vec4(FETCH(uAttachments[POSITION_ATTACHMENT], pixel, s).xyz, 1.0)) > 0.0))
      nonPositive = true;
#else
    float stored = FETCH(uAttachments[POSITION_ATTACHMENT], pixel, s)[DEPTH_CHANNEL];
    if (isBackground(stored)) continue;
    anyGeometry = true;
    if (!(decodeDepth(stored) > 0.0)) nonPositive = true;
#endif
  }
  if (uMode == 0 ? anyGeometry : !nonPositive) discard;
}
