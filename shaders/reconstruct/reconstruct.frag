#version 450 core
// Sub-pixel reconstruction after Chajdas, McGuire and Luebke ("Subpixel Reconstruction Antialiasing",
// I3D 2011), as a retrofit on the tonemapped image. The image was shaded once per pixel; the
// multisampled depth and normals say what each sub-sample sees. A sub-sample on its own pixel's surface
// (depth within Eq. 1 of the pixel's, normals agreeing) keeps the pixel's colour, so interiors and their
// texture detail pass through bit for bit. Any other sub-sample takes the colour of the neighbouring
// shaded pixels whose geometry matches it, weighted by that match and by how near their centres lie
// to the sub-sample: the silhouette pixel becomes the coverage-weighted mix of the surfaces it holds.
// A sub-sample no neighbour matches (a wire thinner than a pixel that no pixel centre hit) cannot be
// rebuilt and keeps the pixel's colour. Colours are mixed in linear light (the display holds sRGB-encoded
// values): averaging the encoded values darkens every blended edge, 0.8 dB of edge PSNR on the demo.
// The plugin prepends SAMPLES, DEPTH_BUFFER_ENCODING, NORMAL_ENCODING, HAS_NORMALS, PACKED_SAMPLE_NORMALS
// and RADIANCE (run on the HDR light target before tonemapping instead of on the display).
#include "common/depth_buffer.glsl"
#include "common/normal.glsl"
layout(binding = 0) uniform sampler2D uInput;           // the display image (or the light target)
layout(binding = 1) uniform sampler2D uPixelDepth;      // the host's single-sample depth buffer
layout(binding = 2) uniform sampler2D uPixelNormal;     // the host's single-sample normal (as encoded)
layout(binding = 3) uniform sampler2DMS uSampleDepth;   // multisampled depth of the same frame
layout(binding = 4) uniform sampler2DMS uSampleNormal;  // its normals (xy only when packed)
uniform vec2 uSamplePositions[SAMPLES];
uniform float uFootprintTan;  // tan(hfov / width)
uniform float uTolerance;     // c of the Eq. 1 style depth test
out vec4 outColour;

const float kSpatialSigma = 0.75;  // pixels: neighbours nearer the sub-sample weigh more

#if RADIANCE  // the HDR light target: already linear
vec3 toLinear(vec3 c) { return c; }
vec3 toDisplay(vec3 c) { return c; }
#else
vec3 toLinear(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c)); }
vec3 toDisplay(vec3 c) { return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c)); }
#endif

struct Geometry {
  float depth;  // metres
  vec3 normal;
  bool background;
};

vec3 unitOrFacing(vec3 n) { return dot(n, n) > 1e-12 ? normalize(n) : vec3(0.0, 0.0, 1.0); }

Geometry pixelGeometry(ivec2 pixel) {
  float z = texelFetch(uPixelDepth, pixel, 0).r;
  Geometry g;
  g.background = depthBufferIsFar(z);
  g.depth = depthBufferToMetres(z);
#if HAS_NORMALS
  g.normal = unitOrFacing(decodeNormal(texelFetch(uPixelNormal, pixel, 0)));
#else
  g.normal = vec3(0.0, 0.0, 1.0);
#endif
  return g;
}

Geometry sampleGeometry(ivec2 pixel, int s) {
  float z = texelFetch(uSampleDepth, pixel, s).r;
  Geometry g;
  g.background = depthBufferIsFar(z);
  g.depth = depthBufferToMetres(z);
#if HAS_NORMALS && NORMAL_ENCODING == NORMAL_OCTAHEDRAL  // two channels, packed or not
  g.normal = decodeNormal(vec4(texelFetch(uSampleNormal, pixel, s).xy, 0.0, 0.0));
#elif HAS_NORMALS && PACKED_SAMPLE_NORMALS
  vec2 xy = texelFetch(uSampleNormal, pixel, s).xy;
  g.normal = unitOrFacing(vec3(xy, sqrt(max(1.0 - dot(xy, xy), 0.0))));
#elif HAS_NORMALS
  g.normal = unitOrFacing(texelFetch(uSampleNormal, pixel, s).xyz);
#else
  g.normal = vec3(0.0, 0.0, 1.0);
#endif
  return g;
}

// How well a shaded pixel stands for a sub-sample: 0 across a depth step (or between geometry and
// background), cos⁸ of the angle between their normals otherwise (0.5 at 24°).
float similarity(Geometry a, Geometry b) {
  if (a.background || b.background) return a.background && b.background ? 1.0 : 0.0;
  if (!(abs(a.depth - b.depth) <= min(a.depth, b.depth) * uFootprintTan * uTolerance)) return 0.0;
  float c = max(dot(a.normal, b.normal), 0.0);
  c *= c;
  c *= c;
  return c * c;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uInput, 0) - 1;
  vec4 centre = texelFetch(uInput, pixel, 0);
  vec3 centreLinear = toLinear(centre.rgb);
  Geometry own = pixelGeometry(pixel);
  vec3 sum = vec3(0.0);
  int rebuilt = 0;
  for (int s = 0; s < SAMPLES; ++s) {
    Geometry g = sampleGeometry(pixel, s);
    if (similarity(g, own) >= 0.5) {
      sum += centreLinear;
      continue;
    }
    ++rebuilt;
    vec2 at = vec2(pixel) + uSamplePositions[s];
    vec3 colour = vec3(0.0);
    float weightSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), last);
        if (q == pixel) continue;
        float w = similarity(g, pixelGeometry(q));
        if (w <= 0.0) continue;
        vec2 offset = at - (vec2(q) + 0.5);
        w *= exp(-dot(offset, offset) / (2.0 * kSpatialSigma * kSpatialSigma));
        colour += w * toLinear(texelFetch(uInput, q, 0).rgb);
        weightSum += w;
      }
    sum += weightSum > 1e-6 ? colour / weightSum : centreLinear;
  }
  outColour = rebuilt == 0 ? centre : vec4(toDisplay(sum / float(SAMPLES)), centre.a);
}
