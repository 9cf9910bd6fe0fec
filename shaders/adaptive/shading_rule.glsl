// Holländer et al.'s shading rule, shared by the shading metric (over a lit pixel's neighbourhood) and
// the geometry metric's emissive term (over a pixel's stored emission):
//   luma on a display-like scale, x / (1 + x); a range below max(t_min, l_max · t_edge) (FXAA's
//   thresholds) needs no more samples, above it c_s · N · range.
uniform float uShadingScale;
uniform float uThresholdMin;
uniform float uThresholdEdge;

float linearLuma(vec3 c) { return dot(max(c, vec3(0.0)), vec3(0.2126, 0.7152, 0.0722)); }
float toDisplay(float l) { return isnan(l) || isinf(l) ? 1.0 : l / (1.0 + l); }
float displayLuma(vec3 c) { return toDisplay(linearLuma(c)); }

float shadingK(float lMin, float lMax, float scale) {
  float range = lMax - lMin;
  return range < max(uThresholdMin, lMax * uThresholdEdge) ? 0.0 : scale * float(SAMPLES) * range;
}
float shadingK(float lMin, float lMax) { return shadingK(lMin, lMax, uShadingScale); }
