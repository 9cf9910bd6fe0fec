#version 450 core
// Pettineo, "Deferred MSAA": the single-sample deferred image, filtered after tonemapping using the
// sub-sample coverage of a multisampled depth buffer. A pixel whose depth sub-samples all agree with
// its single-sample depth is left exactly as it is. Otherwise the samples that differ lie across an
// edge: their mean offset from the pixel centre points at the other side, and their share f of the
// pixel is how much of it the other surface covers. One bilinear tap, f texels towards that side,
// blends (1 − f) of this pixel with f of its neighbour there, in linear light (a coverage is an area:
// mixing gamma-encoded values darkens every blended edge; common/display_encoding.glsl).
// The plugin prepends SAMPLES, DEPTH_BUFFER_ENCODING, DISPLAY_HOLDS_LINEAR, LIT_PER_SAMPLE, FORWARD_MASK (the host draws forward passes: a
// pixel on an edge of what they drew, or one whose tap would read a colour they changed otherwise than
// this pixel's, keeps its colour; the depth here is the opaque surfaces' alone) and COVERAGE_MARK_EDGES.
//
// Two draws (MarkedRewrite, as FXAA's): COVERAGE_MARK_EDGES 1 runs the depth test on every pixel and keeps,
// in a stencil, the pixels it blends; COVERAGE_MARK_EDGES 0 blends those alone, in place. A pixel left as it
// is is not written at all: in one draw every pixel paid the tap's decoding, llvmpipe running both sides of
// the early return under a mask.
#include "common/depth_buffer.glsl"
#include "common/display_encoding.glsl"
layout(binding = 0) uniform sampler2D uInput;        // the display image (linear filtering)
layout(binding = 1) uniform sampler2D uPixelDepth;   // the host's single-sample depth buffer
layout(binding = 2) uniform sampler2DMS uSampleDepth;  // multisampled depth of the same frame
#define FORWARD_MASK_BINDING 3
#include "common/forward_mask.glsl"
#define LIT_PER_SAMPLE_BINDING 4
#include "common/lit_per_sample.glsl"
uniform vec2 uSamplePositions[SAMPLES];
uniform vec2 uTexelSize;
uniform float uFootprintTan;  // tan(hfov / width)
uniform float uTolerance;     // c of the Eq. 1 style depth test
out vec4 outColour;

// uInput's bilinear value at `texel` (pixel units, centres at +0.5), its four texels mixed in linear light.
vec3 linearLightTap(vec2 texel) {
  vec2 corner = texel - 0.5;
  ivec2 base = ivec2(floor(corner));
  vec2 w = corner - floor(corner);
  ivec2 last = textureSize(uInput, 0) - 1;
  vec3 c00 = displayToLinear(texelFetch(uInput, clamp(base, ivec2(0), last), 0).rgb);
  vec3 c10 = displayToLinear(texelFetch(uInput, clamp(base + ivec2(1, 0), ivec2(0), last), 0).rgb);
  vec3 c01 = displayToLinear(texelFetch(uInput, clamp(base + ivec2(0, 1), ivec2(0), last), 0).rgb);
  vec3 c11 = displayToLinear(texelFetch(uInput, clamp(base + ivec2(1, 1), ivec2(0), last), 0).rgb);
  return linearToDisplay(mix(mix(c00, c10, w.x), mix(c01, c11, w.x), w.y));
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(uInput, pixel, 0);
  float zPixel = texelFetch(uPixelDepth, pixel, 0).r;
  bool pixelBackground = depthBufferIsFar(zPixel);
  float dPixel = depthBufferToMetres(zPixel);
  vec2 offsetSum = vec2(0.0);
  int differing = 0;
  for (int s = 0; s < SAMPLES; ++s) {
    float z = texelFetch(uSampleDepth, pixel, s).r;
    bool background = depthBufferIsFar(z);
    float d = depthBufferToMetres(z);
    bool differs = background != pixelBackground ||
                   (!background && abs(d - dPixel) > min(d, dPixel) * uFootprintTan * uTolerance);
    if (differs) {
      offsetSum += uSamplePositions[s] - 0.5;
      ++differing;
    }
  }
  vec2 offset = differing > 0 ? offsetSum / float(differing) : vec2(0.0);
  float longest = max(abs(offset.x), abs(offset.y));
  ivec2 side = ivec2(sign(offset));  // the neighbours the tap below reads besides this pixel
  bool underFilm = underForwardFilm(pixel);
  bool forward = forwardEdge(pixel) || !lendsColour(pixel + ivec2(side.x, 0), underFilm) ||
                 !lendsColour(pixel + ivec2(0, side.y), underFilm) || !lendsColour(pixel + side, underFilm);
#if COVERAGE_MARK_EDGES
  // Left as it is: interior, a symmetric crossing with no side to blend towards, a forward pass's, or lit
  // per sample.
  if (differing == 0 || longest < 1e-6 || forward || litPerSample(pixel)) discard;
#else
  float covered = float(differing) / float(SAMPLES);
  vec2 towards = offset / longest;  // one texel along the dominant axis
  outColour = vec4(linearLightTap(vec2(pixel) + 0.5 + towards * covered), centre.a);
#endif
}
