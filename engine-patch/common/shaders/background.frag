#version 450 core
// The sky, written before the models as FreeSpace Open does: emissive = background, position = marker.
#include "depth_codec.glsl"
#include "gbuffer_outputs.glsl"
uniform mat4 uInverseProjection;
uniform mat3 uViewToWorld;
uniform vec2 uViewportSize;
uniform vec3 uSkyColor;
uniform float uStarDensity;

float hash(vec3 p) {
  p = fract(p * vec3(443.897, 441.423, 437.195));
  p += dot(p, p.yzx + 19.19);
  return fract((p.x + p.y) * p.z);
}

void main() {
  vec2 ndc = gl_FragCoord.xy / uViewportSize * 2.0 - 1.0;
  // Un-projected at the near plane: at the far plane (2e6 m behind a 0.1 m near plane) w is almost 0
  // and single precision turned whole skies black at some aspect ratios.
  vec4 view = uInverseProjection * vec4(ndc, -1.0, 1.0);
  vec3 dir = normalize(uViewToWorld * normalize(view.xyz / view.w));
  vec3 sky = uSkyColor * (0.6 + 0.4 * dir.y);
  // Soft stars (a Gaussian about a pixel wide at test sizes) so the background itself does not alias: each
  // star's falloff is summed from its own cell and the 26 around it, since a star near its cell's border
  // reaches into the next. (Evaluated in its own cell alone, the falloff stopped at the border, a step no
  // sampling rate resolves: every method was off by up to 0.8 at the same star pixels, now 0.1.)
  const float sigma = 0.0035;
  const float cells = 60.0;
  vec3 home = floor(dir * cells);
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        vec3 cell = home + vec3(x, y, z);
        // Only cells the sky's sphere passes through hold a star (the same stars as one cell's test found).
        vec3 low = cell / cells, high = (cell + 1.0) / cells;
        bool onSphere = length(clamp(vec3(0.0), low, high)) <= 1.0 && length(max(abs(low), abs(high))) >= 1.0;
        if (!onSphere || hash(cell) >= 0.03 * uStarDensity) continue;
        vec3 centre = (cell + 0.25 + 0.5 * vec3(hash(cell + 1.0), hash(cell + 2.0), hash(cell + 3.0))) / cells;
        float distance = length(dir - normalize(centre));
        sky += vec3(0.9, 0.9, 1.0) * 4.0 * hash(cell + 4.0) * exp(-distance * distance / (2.0 * sigma * sigma));
      }
  outColor = vec4(0.0);
  outPosition = vec4(0.0, 0.0, kBackgroundMarker, 0.0);
  outNormal = vec4(0.0);
  outSpecular = vec4(0.0);
  outEmissive = vec4(sky, 1.0);
  outVelocity = vec4(0.0);  // the sky reprojects by the camera
}
