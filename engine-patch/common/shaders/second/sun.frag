#version 450 core
// Full-screen pass: the sky where no geometry is, ambient and every directional light elsewhere.
#include "second/surface.glsl"
uniform vec3 uAmbient;
uniform vec3 uSkyColor;
uniform int uDirectionalCount;
uniform vec3 uToLight[4];
uniform vec3 uRadiance[4];
out vec4 outColour;
void main() {
  Surface s = readSurface(ivec2(gl_FragCoord.xy));
  if (s.background) {
    outColour = vec4(uSkyColor * uExposure, 1.0);
    return;
  }
  vec3 colour = uAmbient * s.albedo;
  for (int i = 0; i < uDirectionalCount; ++i) colour += shade(s, uToLight[i], uRadiance[i]);
  outColour = vec4(colour * uExposure, 1.0);
}
