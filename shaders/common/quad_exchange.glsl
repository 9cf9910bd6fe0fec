// The values of the pixel beside this one in its 2x2 quad, across x or across y, taken from the quad's
// fine derivatives instead of fetched again: a neighbourhood pass then fetches only the neighbours outside
// the quad. Exact: each float travels as its two 16-bit halves, whose difference and sum a float holds
// exactly. GL does not say how quads align, so the side the partner lies on comes from the derivative of
// the pixel's parity. Call in uniform control flow, in every fragment of the quad (helpers included,
// with their values fetched at a clamped pixel).

vec4 floatHalves(vec2 v) {
  uvec2 bits = floatBitsToUint(v);
  return vec4(bits >> 16u, bits & 0xffffu);
}
vec2 halvesFloat(vec4 halves) {
  uvec4 bits = uvec4(halves);
  return uintBitsToFloat((bits.xy << 16u) | bits.zw);
}

// +1 where the quad partner across x (y) lies after this pixel, -1 where it lies before.
int quadPartnerSideX() {
  float parity = float(int(gl_FragCoord.x) & 1);
  return (parity == 0.0) == (dFdxFine(parity) > 0.0) ? 1 : -1;
}
int quadPartnerSideY() {
  float parity = float(int(gl_FragCoord.y) & 1);
  return (parity == 0.0) == (dFdyFine(parity) > 0.0) ? 1 : -1;
}

// Two floats of the quad partner across x (y); `side` is quadPartnerSideX() (Y()).
vec2 quadPartnerX(vec2 own, int side) {
  vec4 halves = floatHalves(own);
  return halvesFloat(halves + float(side) * dFdxFine(halves));
}
vec2 quadPartnerY(vec2 own, int side) {
  vec4 halves = floatHalves(own);
  return halvesFloat(halves + float(side) * dFdyFine(halves));
}
