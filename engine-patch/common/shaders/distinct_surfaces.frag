#version 450 core
// The shading floor of a pixel: how many distinct surfaces its samples hold. A primitive's model
// shader runs once per pixel and writes the same values to every sample it covers, so samples whose
// attributes are bit-identical belong to one surface (the plugin's own surface test says the same). Sample
// s counts when no earlier sample equals it in every attachment. Needs SAMPLES and ATTACHMENTS defined.
layout(binding = 0) uniform sampler2DMS uAttachments[ATTACHMENTS];
layout(location = 0) out float outSurfaces;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int surfaces = 0;
  for (int s = 0; s < SAMPLES; ++s) {
    bool seen = false;
    for (int t = 0; t < s; ++t) {
      bool same = true;
      for (int a = 0; a < ATTACHMENTS; ++a)
        same = same && floatBitsToUint(texelFetch(uAttachments[a], pixel, s)) ==
                           floatBitsToUint(texelFetch(uAttachments[a], pixel, t));
      seen = seen || same;
    }
    if (!seen) ++surfaces;
  }
  outSurfaces = float(surfaces);
}
