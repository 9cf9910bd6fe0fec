#include "mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <random>
#include <tuple>

namespace host {

void Mesh::append(const Mesh& other, const glm::mat4& transform) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  const auto base = static_cast<uint32_t>(vertices.size());
  for (const Vertex& v : other.vertices)
    vertices.push_back({glm::vec3(transform * glm::vec4(v.position, 1.0f)), glm::normalize(normalMatrix * v.normal)});
  for (uint32_t i : other.indices) indices.push_back(base + i);
}

namespace generate {

namespace {
// One flat quad (two triangles) with its own four vertices.
void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 normal) {
  const auto base = static_cast<uint32_t>(mesh.vertices.size());
  for (glm::vec3 p : {a, b, c, d}) mesh.vertices.push_back({p, normal});
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}
}  // namespace

Mesh box(glm::vec3 size) {
  Mesh mesh;
  const glm::vec3 h = size * 0.5f;
  // Each face counter-clockwise seen from outside.
  addQuad(mesh, {h.x, -h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, h.y, h.z}, {h.x, -h.y, h.z}, {1, 0, 0});
  addQuad(mesh, {-h.x, -h.y, h.z}, {-h.x, h.y, h.z}, {-h.x, h.y, -h.z}, {-h.x, -h.y, -h.z}, {-1, 0, 0});
  addQuad(mesh, {-h.x, h.y, -h.z}, {-h.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, -h.z}, {0, 1, 0});
  addQuad(mesh, {-h.x, -h.y, h.z}, {-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z}, {0, -1, 0});
  addQuad(mesh, {-h.x, -h.y, h.z}, {h.x, -h.y, h.z}, {h.x, h.y, h.z}, {-h.x, h.y, h.z}, {0, 0, 1});
  addQuad(mesh, {h.x, -h.y, -h.z}, {-h.x, -h.y, -h.z}, {-h.x, h.y, -h.z}, {h.x, h.y, -h.z}, {0, 0, -1});
  return mesh;
}

Mesh plane(glm::vec2 size) {
  Mesh mesh;
  const glm::vec2 h = size * 0.5f;
  addQuad(mesh, {-h.x, 0, h.y}, {h.x, 0, h.y}, {h.x, 0, -h.y}, {-h.x, 0, -h.y}, {0, 1, 0});
  return mesh;
}

Mesh sphere(float radius, int subdivisions) {
  // Latitude-longitude sphere: simple, and exact normals.
  Mesh mesh;
  const int rings = 4 * subdivisions + 4, segments = 8 * subdivisions + 8;
  for (int r = 0; r <= rings; ++r) {
    const float theta = static_cast<float>(M_PI) * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * static_cast<float>(M_PI) * s / segments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.vertices.push_back({n * radius, n});
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
      for (uint32_t i : {a, a + 1, b, a + 1, b + 1, b}) mesh.indices.push_back(i);
    }
  return mesh;
}

Mesh cylinder(float radius, float length, int segments) {
  Mesh mesh;
  for (int s = 0; s <= segments; ++s) {
    const float phi = 2.0f * static_cast<float>(M_PI) * s / segments;
    const glm::vec3 n(std::cos(phi), 0, std::sin(phi));
    mesh.vertices.push_back({n * radius, n});
    mesh.vertices.push_back({n * radius + glm::vec3(0, length, 0), n});
  }
  for (int s = 0; s < segments; ++s) {
    const uint32_t a = 2 * s;
    for (uint32_t i : {a, a + 1, a + 2, a + 1, a + 3, a + 2}) mesh.indices.push_back(i);
  }
  for (int cap = 0; cap < 2; ++cap) {
    const float y = cap ? length : 0.0f;
    const glm::vec3 n(0, cap ? 1.0f : -1.0f, 0);
    const auto centre = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({{0, y, 0}, n});
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * static_cast<float>(M_PI) * s / segments;
      mesh.vertices.push_back({{radius * std::cos(phi), y, radius * std::sin(phi)}, n});
    }
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = centre + 1 + s;
      if (cap)
        for (uint32_t i : {centre, a + 1, a}) mesh.indices.push_back(i);
      else
        for (uint32_t i : {centre, a, a + 1}) mesh.indices.push_back(i);
    }
  }
  return mesh;
}

Mesh greebledHull(const GreebledHull& params) {
  Mesh mesh = box(params.size);
  std::mt19937 rng(params.seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const glm::vec3 half = params.size * 0.5f;
  for (int g = 0; g < params.greebles; ++g) {
    // Pick a face weighted by area so panels spread evenly.
    const float areas[3] = {params.size.y * params.size.z, params.size.x * params.size.z,
                            params.size.x * params.size.y};
    const float pick = unit(rng) * (areas[0] + areas[1] + areas[2]);
    const int axis = pick < areas[0] ? 0 : (pick < areas[0] + areas[1] ? 1 : 2);
    const float side = unit(rng) < 0.5f ? -1.0f : 1.0f;
    glm::vec3 extent;
    for (int i = 0; i < 3; ++i) extent[i] = params.greebleMin + (params.greebleMax - params.greebleMin) * unit(rng);
    extent[axis] *= 0.5f;  // panels are flatter than they are wide
    glm::vec3 centre;
    for (int i = 0; i < 3; ++i) centre[i] = (unit(rng) * 2.0f - 1.0f) * (half[i] - extent[i] * 0.5f);
    centre[axis] = side * (half[axis] + extent[axis] * 0.5f);
    Mesh panel = box(extent);
    // Tilt the panel's normals (not its positions): the noisy-normal hard case.
    const glm::vec3 tiltAxis = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) - 0.5f + 1e-3f);
    const glm::mat3 tilt(glm::rotate(glm::mat4(1.0f), params.normalNoise * unit(rng), tiltAxis));
    for (Vertex& v : panel.vertices) v.normal = glm::normalize(tilt * v.normal);
    mesh.append(panel, glm::translate(glm::mat4(1.0f), centre));
  }
  return mesh;
}

}  // namespace generate

namespace {

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Appends the node's meshes in world space. Faces that index past their mesh or touch a vertex whose
// position or normal is not finite are dropped and counted per mesh (`dropped`: mesh name, dropped,
// faces), so the caller can refuse a model with nothing usable and warn about one with some.
void appendNode(Mesh& mesh, const aiScene& scene, const aiNode& node, const glm::mat4& parent,
                std::vector<std::tuple<std::string, unsigned, unsigned>>& dropped) {
  glm::mat4 local;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) local[c][r] = node.mTransformation[r][c];  // aiMatrix is row-major
  const glm::mat4 world = parent * local;
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& source = *scene.mMeshes[node.mMeshes[m]];
    if (!source.HasNormals()) continue;  // aiProcess_GenSmoothNormals guarantees them for triangles
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    std::vector<bool> usable(source.mNumVertices);
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D& p = source.mVertices[v];
      const aiVector3D& n = source.mNormals[v];
      glm::vec3 normal = normalMatrix * glm::vec3(n.x, n.y, n.z);
      const float length = glm::length(normal);
      const glm::vec3 position = glm::vec3(world * glm::vec4(p.x, p.y, p.z, 1.0f));
      usable[v] = isFinite(position) && isFinite(normal);
      // An unusable vertex stays (indices keep their meaning) but at the origin: no face draws it, and
      // nothing that sums vertices (bounds) sees a NaN.
      mesh.vertices.push_back(
          {usable[v] ? position : glm::vec3(0.0f), usable[v] && length > 0.0f ? normal / length : glm::vec3(0, 1, 0)});
    }
    unsigned triangles = 0, bad = 0;
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& face = source.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines after triangulation
      ++triangles;
      bool ok = true;
      for (unsigned i = 0; i < 3; ++i) ok = ok && face.mIndices[i] < source.mNumVertices && usable[face.mIndices[i]];
      if (!ok) {
        ++bad;
        continue;
      }
      for (unsigned i = 0; i < 3; ++i) mesh.indices.push_back(base + face.mIndices[i]);
    }
    if (bad) dropped.emplace_back(source.mName.C_Str(), bad, triangles);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(mesh, scene, *node.mChildren[c], world, dropped);
}

}  // namespace

Mesh loadModel(const std::string& path, std::vector<std::string>* warnings) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                     aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) throw ModelLoadError(path + ": cannot load model: " + importer.GetErrorString());
  Mesh mesh;
  std::vector<std::tuple<std::string, unsigned, unsigned>> dropped;
  appendNode(mesh, *scene, *scene->mRootNode, glm::mat4(1.0f), dropped);
  for (const auto& [name, bad, triangles] : dropped) {
    const std::string what = path + ": mesh '" + name + "': " + std::to_string(bad) + " of " +
                             std::to_string(triangles) +
                             " triangles have non-finite positions or normals or indices out of range";
    if (mesh.indices.empty()) throw ModelLoadError(what + "; nothing of the model is usable");
    if (warnings)
      warnings->push_back(what + "; they are left out");
    else
      std::fprintf(stderr, "retroaa: warning: %s; they are left out\n", what.c_str());
  }
  if (mesh.indices.empty()) throw ModelLoadError(path + ": model has no triangles");
  return mesh;
}

}  // namespace host
