// Triangle meshes for the host: procedural generators (deterministic for a seed) and model files.
#pragma once

#include "texture_image.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace host {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv{0.0f};  // texture coordinates; the generators' run in metres along the surface
  // Tangent-space frame of the normal map: xyz the direction of increasing u, w the sign that makes
  // cross(normal, xyz) · w the direction of increasing v.
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;

  void append(const Mesh& other, const glm::mat4& transform);
  size_t triangleCount() const { return indices.size() / 3; }
};

// Per-vertex tangents from the texture coordinates (each triangle's du direction, area-weighted, made
// orthogonal to the normal); any perpendicular where the coordinates are degenerate.
void computeTangents(Mesh& mesh);

namespace generate {
Mesh box(glm::vec3 size);
Mesh plane(glm::vec2 size);  // in the xz plane, normal +y
Mesh sphere(float radius, int subdivisions);
Mesh cylinder(float radius, float length, int segments);  // along +y, base at origin, capped

// A hull with sub-pixel panel detail: `greebles` small boxes scattered over the surface of a box
// of `size`, each between `greebleMin` and `greebleMax` on a side, each with its normals tilted by up
// to `normalNoise` radians so that neighbouring panels catch light differently (intra-model aliasing).
struct GreebledHull {
  glm::vec3 size{4, 1.5, 10};
  int greebles = 400;
  float greebleMin = 0.02f;
  float greebleMax = 0.2f;
  float normalNoise = 0.15f;
  uint32_t seed = 1;
};
Mesh greebledHull(const GreebledHull& params);
}  // namespace generate

class ModelLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One material's share of a model: its meshes merged, and what the file says of the material.
struct ModelPart {
  Mesh mesh;
  std::string materialName;
  glm::vec3 albedo{1.0f}, emissive{0.0f};
  MaterialMaps maps;  // base colour, normal and emissive textures, external files or embedded
};

// glTF 2.0, OBJ and the other formats assimp reads; meshes merged per material, node transforms
// applied, texture coordinates top-down (row 0 of an image at v = 0; a mesh without any gets a box
// projection of its positions). Faces with non-finite positions
// or normals, or indices out of range, are left out: with a warning naming file, mesh and counts (into
// `warnings`, else to stderr), or ModelLoadError when nothing is left; so is a texture that cannot be
// read (TextureError's message).
enum class ModelTextures { Read, Skip };  // Skip: the parts' maps stay empty (a scene overrides the material)
std::vector<ModelPart> loadModel(const std::string& path, std::vector<std::string>* warnings = nullptr,
                                 ModelTextures textures = ModelTextures::Read);
// Every part merged into one mesh (models whose materials a scene overrides).
Mesh mergeParts(const std::vector<ModelPart>& parts);

}  // namespace host
