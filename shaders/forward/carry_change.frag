#version 450 core
// The forward target before fill: what the host drew into its scene colour between shade() and
// beginForward() (a glow composited over the lit image, say) reaches the samples the slices kept, as the
// pixel's change (exact for what adds to the pixel, its mean for what blends over it). Blended in with the
// destination's alpha: 1 in a kept sample, 0 elsewhere (fill gives those the pixel's colour, change and all).
layout(binding = 0) uniform sampler2D uSceneColour;  // now
layout(binding = 1) uniform sampler2D uShadedColour;  // as shade() left it
out vec4 outColour;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  outColour = vec4(texelFetch(uSceneColour, pixel, 0).rgb - texelFetch(uShadedColour, pixel, 0).rgb, 0.0);
}
