// ACES filmic fit (Narkowicz 2015) and the sRGB transfer function.
vec3 tonemapACES(vec3 x) {
  x = max(x, vec3(0.0));
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 linearToSrgb(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 displayColour(vec3 hdr, float exposure) { return linearToSrgb(tonemapACES(hdr * exposure)); }
