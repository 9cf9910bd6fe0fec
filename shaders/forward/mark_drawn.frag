#version 450 core
// The forward mask: 1 where the host's forward passes changed the scene colour, against the copy kept at
// beginForward(). A change within 1/256 of the value (the forward target's half-float round trip, a blend
// that adds nothing visible) is no draw a post pass must keep its neighbours' colours out of.
layout(binding = 0) uniform sampler2D uBefore;  // the scene colour as shade() left it
layout(binding = 1) uniform sampler2D uAfter;   // the scene colour after the forward passes
out float outDrawn;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 before = texelFetch(uBefore, pixel, 0).rgb;
  vec3 after = texelFetch(uAfter, pixel, 0).rgb;
  vec3 tolerance = max(max(abs(before), abs(after)) / 256.0, vec3(1e-6));
  outDrawn = any(greaterThan(abs(after - before), tolerance)) ? 1.0 : 0.0;
}
