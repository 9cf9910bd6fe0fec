// Both hosts' material: constants times maps (material_textures.h binds them; 1×1 neutral textures
// where a material has none). Texture coordinates times uUvScale; normal maps in tangent space.
layout(binding = 0) uniform sampler2D uAlbedoMap;    // sRGB: filtered in linear
layout(binding = 1) uniform sampler2D uNormalMap;    // xyz · 0.5 + 0.5
layout(binding = 2) uniform sampler2D uSpecularMap;  // specular multiplier, gloss multiplier in alpha
layout(binding = 3) uniform sampler2D uEmissiveMap;  // sRGB
uniform float uUvScale;
uniform bool uNormalMapped;  // false: the neutral texture, whose 128/255 is not exactly flat

// The shading normal: the interpolated one (facing the viewer on back faces) bent by the normal map.
vec3 mappedNormal(vec3 normal, vec4 tangent, vec2 uv, bool frontFacing) {
  vec3 n = normalize(normal);
  if (!frontFacing) n = -n;
  if (!uNormalMapped) return n;
  vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
  if (!(dot(t, t) > 1e-12)) return n;  // no usable frame
  t = normalize(t);
  vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 m = texture(uNormalMap, uv * uUvScale).xyz * 2.0 - 1.0;
  vec3 bent = t * m.x + b * m.y + n * max(m.z, 0.0);
  return dot(bent, bent) > 0.0 ? normalize(bent) : n;
}
vec3 albedoAt(vec2 uv) { return texture(uAlbedoMap, uv * uUvScale).rgb; }
vec4 specularAt(vec2 uv) { return texture(uSpecularMap, uv * uUvScale); }
vec3 emissiveAt(vec2 uv) { return texture(uEmissiveMap, uv * uUvScale).rgb; }
