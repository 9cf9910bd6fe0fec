#include "mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <map>
#include <optional>
#include <random>
#include <tuple>

namespace host {

void Mesh::append(const Mesh& other, const glm::mat4& transform) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  const auto base = static_cast<uint32_t>(vertices.size());
  const glm::mat3 linear(transform);
  // A mirroring transform flips the frame's handedness.
  const float handedness = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
  for (const Vertex& v : other.vertices)
    vertices.push_back({glm::vec3(transform * glm::vec4(v.position, 1.0f)), glm::normalize(normalMatrix * v.normal),
                        v.uv, glm::vec4(glm::normalize(linear * glm::vec3(v.tangent)), v.tangent.w * handedness)});
  for (uint32_t i : other.indices) indices.push_back(base + i);
}

void computeTangents(Mesh& mesh) {
  std::vector<glm::vec3> du(mesh.vertices.size(), glm::vec3(0.0f)), dv(mesh.vertices.size(), glm::vec3(0.0f));
  for (size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
    const uint32_t i[3] = {mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]};
    const Vertex &a = mesh.vertices[i[0]], &b = mesh.vertices[i[1]], &c = mesh.vertices[i[2]];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 t1 = b.uv - a.uv, t2 = c.uv - a.uv;
    const float det = t1.x * t2.y - t2.x * t1.y;
    if (!(std::fabs(det) > 1e-12f)) continue;
    // Not divided by det: larger triangles (in texture space too) weigh more, and the sign stays.
    const glm::vec3 u = (e1 * t2.y - e2 * t1.y) * (det > 0 ? 1.0f : -1.0f);
    const glm::vec3 v = (e2 * t1.x - e1 * t2.x) * (det > 0 ? 1.0f : -1.0f);
    for (uint32_t k : i) du[k] += u, dv[k] += v;
  }
  for (size_t k = 0; k < mesh.vertices.size(); ++k) {
    Vertex& vertex = mesh.vertices[k];
    const glm::vec3 n = vertex.normal;
    glm::vec3 t = du[k] - n * glm::dot(n, du[k]);
    if (!(glm::dot(t, t) > 1e-20f)) {  // no texture-space direction: any perpendicular
      t = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
      t -= n * glm::dot(n, t);
    }
    t = glm::normalize(t);
    vertex.tangent = glm::vec4(t, glm::dot(glm::cross(n, t), dv[k]) < 0.0f ? -1.0f : 1.0f);
  }
}

namespace generate {

namespace {
// One flat quad (two triangles) with its own four vertices; u runs from a to d, v from a to b, in
// metres measured from the origin's projection (coplanar quads continue one another's texture).
void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 normal) {
  const auto base = static_cast<uint32_t>(mesh.vertices.size());
  const glm::vec3 uAxis = glm::normalize(d - a), vAxis = glm::normalize(b - a);
  for (glm::vec3 p : {a, b, c, d}) mesh.vertices.push_back({p, normal, {glm::dot(p, uAxis), glm::dot(p, vAxis)}});
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
  computeTangents(mesh);
  return mesh;
}

Mesh plane(glm::vec2 size) {
  Mesh mesh;
  const glm::vec2 h = size * 0.5f;
  addQuad(mesh, {-h.x, 0, h.y}, {h.x, 0, h.y}, {h.x, 0, -h.y}, {-h.x, 0, -h.y}, {0, 1, 0});
  computeTangents(mesh);
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
      mesh.vertices.push_back({n * radius, n, {phi * radius, theta * radius}});
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
      for (uint32_t i : {a, a + 1, b, a + 1, b + 1, b}) mesh.indices.push_back(i);
    }
  computeTangents(mesh);
  return mesh;
}

Mesh cylinder(float radius, float length, int segments) {
  Mesh mesh;
  for (int s = 0; s <= segments; ++s) {
    const float phi = 2.0f * static_cast<float>(M_PI) * s / segments;
    const glm::vec3 n(std::cos(phi), 0, std::sin(phi));
    mesh.vertices.push_back({n * radius, n, {phi * radius, 0.0f}});
    mesh.vertices.push_back({n * radius + glm::vec3(0, length, 0), n, {phi * radius, length}});
  }
  for (int s = 0; s < segments; ++s) {
    const uint32_t a = 2 * s;
    for (uint32_t i : {a, a + 1, a + 2, a + 1, a + 3, a + 2}) mesh.indices.push_back(i);
  }
  for (int cap = 0; cap < 2; ++cap) {
    const float y = cap ? length : 0.0f;
    const glm::vec3 n(0, cap ? 1.0f : -1.0f, 0);
    const auto centre = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({{0, y, 0}, n, {0.0f, 0.0f}});
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * static_cast<float>(M_PI) * s / segments;
      const glm::vec2 rim(radius * std::cos(phi), radius * std::sin(phi));
      mesh.vertices.push_back({{rim.x, y, rim.y}, n, rim});
    }
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = centre + 1 + s;
      if (cap)
        for (uint32_t i : {centre, a + 1, a}) mesh.indices.push_back(i);
      else
        for (uint32_t i : {centre, a, a + 1}) mesh.indices.push_back(i);
    }
  }
  computeTangents(mesh);
  return mesh;
}

Mesh greebledHull(const GreebledHull& params) {
  Mesh mesh = box(params.size);
  // Exactly what it will hold, so growth never doubles it (the scene's budget counts these bytes).
  mesh.vertices.reserve(mesh.vertices.size() * (1 + size_t(params.greebles)));
  mesh.indices.reserve(mesh.indices.size() * (1 + size_t(params.greebles)));
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

// Appends the node's meshes in world space, each to its material's part. Faces that index past their
// mesh or touch a vertex whose position or normal is not finite are dropped and counted per mesh
// (`dropped`: mesh name, dropped, faces), so the caller can refuse a model with nothing usable and warn
// about one with some.
void appendNode(std::vector<Mesh>& parts, const aiScene& scene, const aiNode& node, const glm::mat4& parent,
                std::vector<std::tuple<std::string, unsigned, unsigned>>& dropped) {
  glm::mat4 local;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) local[c][r] = node.mTransformation[r][c];  // aiMatrix is row-major
  const glm::mat4 world = parent * local;
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& source = *scene.mMeshes[node.mMeshes[m]];
    if (!source.HasNormals()) continue;  // aiProcess_GenSmoothNormals guarantees them for triangles
    Mesh& mesh = parts[std::min<size_t>(source.mMaterialIndex, parts.size() - 1)];
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    std::vector<bool> usable(source.mNumVertices);
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D& p = source.mVertices[v];
      const aiVector3D& n = source.mNormals[v];
      glm::vec3 normal = normalMatrix * glm::vec3(n.x, n.y, n.z);
      const float length = glm::length(normal);
      const glm::vec3 position = glm::vec3(world * glm::vec4(p.x, p.y, p.z, 1.0f));
      glm::vec2 uv;
      if (source.HasTextureCoords(0)) {
        uv = {source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y};
      } else {
        // No coordinates in the file: a box projection of the position, on the plane the normal faces
        // most (model units, as the generators' metres), so a scene's maps still land on the model.
        const glm::vec3 a = glm::abs(normal);
        uv = a.x >= a.y && a.x >= a.z ? glm::vec2(position.z, position.y)
             : a.y >= a.z             ? glm::vec2(position.x, position.z)
                                      : glm::vec2(position.x, position.y);
      }
      usable[v] = isFinite(position) && isFinite(normal) && std::isfinite(uv.x) && std::isfinite(uv.y);
      // An unusable vertex stays (indices keep their meaning) but at the origin: no face draws it, and
      // nothing that sums vertices (bounds) sees a NaN.
      mesh.vertices.push_back({usable[v] ? position : glm::vec3(0.0f),
                               usable[v] && length > 0.0f ? normal / length : glm::vec3(0, 1, 0),
                               usable[v] ? uv : glm::vec2(0.0f)});
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
  for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(parts, scene, *node.mChildren[c], world, dropped);
}

// One of the material's textures of `type`: embedded ("*0", or a name the file embeds) or a file beside
// the model. Null when the material has none.
SharedTextureImage readMaterialTexture(const aiScene& scene, const aiMaterial& material, aiTextureType type,
                                       const std::filesystem::path& modelDirectory,
                                       std::map<std::string, SharedTextureImage>& cache) {
  aiString name;
  if (material.GetTextureCount(type) == 0 || material.GetTexture(type, 0, &name) != AI_SUCCESS) return nullptr;
  const std::string key = name.C_Str();
  if (const auto found = cache.find(key); found != cache.end()) return found->second;
  SharedTextureImage image;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.C_Str())) {
    const std::string label = "embedded texture '" + key + "'";
    if (embedded->mHeight == 0) {  // compressed (PNG, JPEG...): mWidth bytes
      image = decodeTextureBytes(reinterpret_cast<const uint8_t*>(embedded->pcData), embedded->mWidth,
                                 embedded->achFormatHint, label);
    } else {  // raw BGRA texels
      if (embedded->mWidth > unsigned(kMaxTextureSide) || embedded->mHeight > unsigned(kMaxTextureSide))
        throw TextureError(label + ": larger than " + std::to_string(kMaxTextureSide) + " texels on a side");
      auto raw = std::make_shared<TextureImage>();
      raw->width = int(embedded->mWidth), raw->height = int(embedded->mHeight), raw->label = label;
      for (size_t t = 0; t < size_t(raw->width) * raw->height; ++t) {
        const aiTexel& texel = embedded->pcData[t];
        raw->rgba.insert(raw->rgba.end(), {texel.r, texel.g, texel.b, texel.a});
      }
      image = raw;
    }
  } else {
    // Files written on Windows name their textures with backslashes (".\\tex.jpg"): a separator here too.
    std::string relative = key;
    std::replace(relative.begin(), relative.end(), '\\', '/');
    image = readTextureFile((modelDirectory / relative).string());
  }
  size_t bytes = image->rgba.size();
  for (const auto& [other, held] : cache) bytes += held->rgba.size();
  if (bytes > kMaxSceneTextureBytes)
    throw TextureError("the model's textures exceed " + std::to_string(kMaxSceneTextureBytes >> 20) + " MiB");
  return cache[key] = image;
}

// Some of what assimp leaves out it says only in its log: a glTF face whose index lies past its
// vertices is dropped inside the importer, before appendNode could count it. While it lives, this
// collects the log's warnings about data dropped so that the loader can pass them on.
class DroppedDataLog : public Assimp::LogStream {
 public:
  DroppedDataLog() : ownsLogger_(Assimp::DefaultLogger::isNullLogger()) {
    if (ownsLogger_) Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(this, Assimp::Logger::Warn | Assimp::Logger::Err);
  }
  ~DroppedDataLog() override {
    Assimp::DefaultLogger::get()->detachStream(this, Assimp::Logger::Warn | Assimp::Logger::Err);
    if (ownsLogger_) Assimp::DefaultLogger::kill();
  }
  void write(const char* message) override {
    std::string text = message;
    if (text.find("dropped") == std::string::npos && text.find("out-of-range") == std::string::npos) return;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    const size_t colon = text.find(": ");  // "Warn,  T0: …": the level and thread are assimp's
    messages.push_back(colon == std::string::npos ? text : text.substr(colon + 2));
  }
  std::vector<std::string> messages;

 private:
  bool ownsLogger_;
};

// The triangles a glTF file declares (its primitives of mode 4: their index count, or their vertex count
// without indices, over 3), read from its JSON (.gltf, or a .glb's JSON chunk); nullopt for other files. assimp
// drops a face with an index past its vertices and says only that some were: this counts them.
std::optional<size_t> declaredGltfTriangles(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if ((extension != ".gltf" && extension != ".glb") || error || bytes > (std::uintmax_t(256) << 20))
    return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (extension == ".glb") {  // 12-byte header, then the JSON chunk: its length, "JSON", its bytes
    if (text.size() < 20 || text.compare(16, 4, "JSON") != 0) return std::nullopt;
    uint32_t length = 0;
    std::memcpy(&length, text.data() + 12, 4);
    if (length > text.size() - 20) return std::nullopt;
    text = text.substr(20, length);
  }
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (!document.is_object() || !document.contains("meshes") || !document.contains("accessors")) return std::nullopt;
  try {  // a file assimp read may still hold fields of the wrong type: then nothing is counted
    const nlohmann::json& accessors = document.at("accessors");
    auto countOf = [&accessors](const nlohmann::json& index) -> size_t {
      if (!index.is_number_unsigned() || index.get<size_t>() >= accessors.size()) return 0;
      return accessors.at(index.get<size_t>()).value("count", size_t(0));
    };
    size_t triangles = 0;
    for (const nlohmann::json& mesh : document.at("meshes"))
      for (const nlohmann::json& primitive : mesh.value("primitives", nlohmann::json::array()))
        if (primitive.value("mode", 4) == 4)
          triangles +=
              (primitive.contains("indices")
                   ? countOf(primitive.at("indices"))
                   : countOf(
                         primitive.value("attributes", nlohmann::json::object()).value("POSITION", nlohmann::json()))) /
              3;
    return triangles;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::vector<ModelPart> loadModel(const std::string& path, std::vector<std::string>* warnings, ModelTextures textures) {
  Assimp::Importer importer;
  DroppedDataLog log;
  // FlipUVs: assimp turns glTF's top-down coordinates (and OBJ's bottom-up ones) into bottom-up; images
  // are uploaded top-down, so every format is brought back to top-down.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                                  aiProcess_SortByPType | aiProcess_FlipUVs);
  if (!scene || !scene->mRootNode) throw ModelLoadError(path + ": cannot load model: " + importer.GetErrorString());
  auto warn = [warnings](const std::string& what) {
    if (warnings)
      warnings->push_back(what);
    else
      std::fprintf(stderr, "retroaa: warning: %s\n", what.c_str());
  };
  const bool droppedFaces = std::any_of(log.messages.begin(), log.messages.end(), [](const std::string& message) {
    return message.find("out-of-range") != std::string::npos;
  });
  const size_t declared = droppedFaces ? declaredGltfTriangles(path).value_or(0) : 0;  // 0: not counted
  size_t imported = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) imported += scene->mMeshes[m]->mNumFaces;
  for (const std::string& message : log.messages) {
    if (declared > imported && message.find("out-of-range") != std::string::npos)
      warn(path + ": " + std::to_string(declared - imported) + " of " + std::to_string(declared) +
           " faces had out-of-range indices; they are left out");
    else
      warn(path + ": " + message);
  }
  std::vector<Mesh> meshes(std::max(1u, scene->mNumMaterials));
  std::vector<std::tuple<std::string, unsigned, unsigned>> dropped;
  appendNode(meshes, *scene, *scene->mRootNode, glm::mat4(1.0f), dropped);
  size_t indices = 0;
  for (const Mesh& mesh : meshes) indices += mesh.indices.size();
  for (const auto& [name, bad, triangles] : dropped) {
    const std::string what = path + ": mesh '" + name + "': " + std::to_string(bad) + " of " +
                             std::to_string(triangles) +
                             " triangles have non-finite positions or normals or indices out of range";
    if (indices == 0) throw ModelLoadError(what + "; nothing of the model is usable");
    warn(what + "; they are left out");
  }
  if (indices == 0) throw ModelLoadError(path + ": model has no triangles");

  std::vector<ModelPart> parts;
  std::map<std::string, SharedTextureImage> cache;
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (meshes[m].indices.empty()) continue;
    ModelPart part;
    part.mesh = std::move(meshes[m]);
    computeTangents(part.mesh);
    if (m < scene->mNumMaterials) {
      const aiMaterial& material = *scene->mMaterials[m];
      part.materialName = material.GetName().C_Str();
      aiColor4D colour;
      if (material.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS ||
          material.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
        part.albedo = glm::clamp(glm::vec3(colour.r, colour.g, colour.b), 0.0f, 1.0f);
      if (material.Get(AI_MATKEY_COLOR_EMISSIVE, colour) == AI_SUCCESS)
        part.emissive = glm::clamp(glm::vec3(colour.r, colour.g, colour.b), 0.0f, 1e4f);
      if (textures == ModelTextures::Read) try {
          part.maps.albedo = readMaterialTexture(*scene, material, aiTextureType_BASE_COLOR, directory, cache);
          if (!part.maps.albedo)
            part.maps.albedo = readMaterialTexture(*scene, material, aiTextureType_DIFFUSE, directory, cache);
          part.maps.normal = readMaterialTexture(*scene, material, aiTextureType_NORMALS, directory, cache);
          part.maps.emissive = readMaterialTexture(*scene, material, aiTextureType_EMISSIVE, directory, cache);
        } catch (const TextureError& e) {
          throw ModelLoadError(path + ": material '" + part.materialName + "': " + e.what());
        }
      // An emissive texture with no factor: the texture is the emission.
      if (part.maps.emissive && glm::dot(part.emissive, glm::vec3(1.0f)) <= 0.0f) part.emissive = glm::vec3(1.0f);
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

Mesh mergeParts(const std::vector<ModelPart>& parts) {
  Mesh merged;
  for (const ModelPart& part : parts) merged.append(part.mesh, glm::mat4(1.0f));
  return merged;
}

}  // namespace host
