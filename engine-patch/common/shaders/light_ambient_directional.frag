#version 450 core
#include "lighting_common.glsl"
uniform vec3 uAmbient;
uniform int uDirectionalCount;
uniform vec3 uToLight[4];   // view space, unit
uniform vec3 uRadiance[4];
out vec4 outLight;
void main() {
  Surface s = readSurface(ivec2(gl_FragCoord.xy));
  if (s.background) discard;
  vec3 light = uAmbient * s.albedo;
  for (int i = 0; i < uDirectionalCount; ++i) light += shade(s, uToLight[i], uRadiance[i]);
  outLight = vec4(light, 1.0);
}
