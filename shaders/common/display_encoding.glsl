// The sRGB transfer functions (IEC 61966-2-1), and what the display's stored values are.
// DISPLAY_HOLDS_LINEAR (the plugin prepends it: GBufferLayout::displayEncoding Linear on a non-sRGB format):
// the display holds linear light, shown as stored. Otherwise it holds gamma-encoded values. A pass that
// mixes colours mixes linear light, and one that thresholds contrast thresholds perceptual values, either way.
vec3 srgbDecode(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c)); }
vec3 srgbEncode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

#if DISPLAY_HOLDS_LINEAR
vec3 displayToLinear(vec3 stored) { return stored; }
vec3 linearToDisplay(vec3 linear) { return linear; }
vec3 displayToPerceptual(vec3 stored) { return srgbEncode(stored); }
#else
vec3 displayToLinear(vec3 stored) { return srgbDecode(stored); }
vec3 linearToDisplay(vec3 linear) { return srgbEncode(linear); }
vec3 displayToPerceptual(vec3 stored) { return stored; }
#endif
