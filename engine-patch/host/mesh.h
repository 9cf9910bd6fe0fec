// Triangle meshes for the host: procedural generators (deterministic for a seed) and model files.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace host {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;

  void append(const Mesh& other, const glm::mat4& transform);
  size_t triangleCount() const { return indices.size() / 3; }
};

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

// glTF 2.0, OBJ and the other formats assimp reads; all meshes merged, node transforms applied.
// Faces with non-finite positions or normals, or indices out of range, are left out: with a warning
// naming file, mesh and counts (into `warnings`, else to stderr), or ModelLoadError when nothing is left.
Mesh loadModel(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace host
