#version 450 core
// After the host's forward passes: the box mean of each pixel's SAMPLES samples into the scene colour,
// as the slices' composite averages them (a transparent's edge crossing a pixel keeps its coverage).
layout(binding = 0) uniform sampler2DMS uForward;
out vec4 outColour;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 sum = vec4(0.0);
  for (int s = 0; s < SAMPLES; ++s) sum += texelFetch(uForward, pixel, s);
  outColour = sum / float(SAMPLES);
}
