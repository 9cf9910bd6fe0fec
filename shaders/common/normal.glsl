// The host's normal encoding (retroaa::NormalEncoding, injected as NORMAL_ENCODING): every pass works
// on decoded normals and re-encodes what it writes.
#if NORMAL_ENCODING == NORMAL_OCTAHEDRAL
// Octahedral mapping (Cigolle et al., "A Survey of Efficient Representations for Independent Unit
// Vectors", JCGT 2014): the unit sphere folded onto the square [-1, 1]² through the octahedron.
vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }
#endif

// The stored normal as a vector: xyz as stored (not normalised, as the host wrote it), or the unit
// vector an octahedral or spheremap pair names.
vec3 decodeNormal(vec4 stored) {
#if NORMAL_ENCODING == NORMAL_OCTAHEDRAL
  vec3 n = vec3(stored.xy, 1.0 - abs(stored.x) - abs(stored.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
  return normalize(n);
#elif NORMAL_ENCODING == NORMAL_SPHEREMAP
  // The pair's length holds z, its direction xy's; a zero pair is the normal facing straight away
  // (where the host's own normalize() would give NaN).
  vec2 e = stored.xy * 2.0 - 1.0;
  float lengthSquared = dot(e, e);
  float z = clamp(lengthSquared * 2.0 - 1.0, -1.0, 1.0);
  vec2 direction = lengthSquared > 0.0 ? e * inversesqrt(lengthSquared) : vec2(0.0);
  return vec3(direction * sqrt(1.0 - z * z), z);
#else
  return stored.xyz;
#endif
}

// `stored` with its normal replaced by the unit vector `n`; the other channels kept.
vec4 encodeNormal(vec4 stored, vec3 n) {
#if NORMAL_ENCODING == NORMAL_OCTAHEDRAL
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 folded = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * signNotZero(n.xy);
  return vec4(folded, stored.zw);
#elif NORMAL_ENCODING == NORMAL_SPHEREMAP
  float xyLength = length(n.xy);
  vec2 direction = xyLength > 0.0 ? n.xy / xyLength : vec2(1.0, 0.0);  // n = ±z: any direction will do
  return vec4(direction * sqrt(clamp(n.z * 0.5 + 0.5, 0.0, 1.0)) * 0.5 + 0.5, stored.zw);
#else
  return vec4(n, stored.w);
#endif
}

// An encoding that cannot hold a zero-length normal (octahedral, spheremap) needs no replacement for one.
const bool kNormalCanBeZero = NORMAL_ENCODING == NORMAL_XYZ;
