#version 450 core
// Point and tube lights drawn as volumes; fragments outside the light's radius are discarded.
#include "lighting_common.glsl"
uniform vec3 uStart;  // view space
uniform vec3 uEnd;    // equals uStart for a point light
uniform vec3 uRadiance;
uniform float uRadius;
out vec4 outLight;
void main() {
  Surface s = readSurface(ivec2(gl_FragCoord.xy));
  if (s.background) discard;
  // A tube lights like a point at the closest spot of its segment (representative point).
  vec3 segment = uEnd - uStart;
  float t = dot(segment, segment) > 0.0 ? clamp(dot(s.position - uStart, segment) / dot(segment, segment), 0.0, 1.0) : 0.0;
  vec3 toLight = uStart + t * segment - s.position;
  float distance = length(toLight);
  if (distance >= uRadius || distance <= 0.0) discard;
  float window = 1.0 - pow(distance / uRadius, 4.0);
  float attenuation = window * window / (distance * distance + 1.0);
  outLight = vec4(shade(s, toLight / distance, uRadiance * attenuation), 1.0);
}
