#version 450 core
// One point light, added to what is lit so far. A smooth window brings it to 0 at its radius.
#include "second/surface.glsl"
uniform vec3 uCentre;
uniform float uRadius;
uniform vec3 uRadiance;
out vec4 outColour;
void main() {
  Surface s = readSurface(ivec2(gl_FragCoord.xy));
  if (s.background) discard;
  vec3 toLight = uCentre - s.position;
  float distance = length(toLight);
  if (distance >= uRadius) discard;
  float window = 1.0 - pow(distance / uRadius, 4.0);
  float falloff = window * window / (distance * distance + 1.0);
  outColour = vec4(shade(s, toLight / distance, uRadiance * falloff) * uExposure, 0.0);
}
