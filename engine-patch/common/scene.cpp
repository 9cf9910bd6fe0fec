#include "scene.h"

#include "bounded_json.h"
#include "procedural.h"

#include "gl_objects.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>

namespace host {

namespace {

using nlohmann::json;

// What a scene's meshes may hold, each repeat its own copy; the host uploads each, so the GPU holds as
// much again. 8 greebled hulls of 200 000 greebles (19.2 M triangles, 2.1 GB) took 4.5 GB in all; the
// demo scene holds 14 MiB.
constexpr size_t kMaxSceneGeometryBytes = size_t(512) << 20;
// A model file (with the buffers a .gltf names) that assimp reads whole before any of it can be counted.
constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t(64) << 20;
// Each object holds its own mesh and draw call: a million small ones took 7.6 GB before this cap.
constexpr size_t kMaxSceneObjects = 65'536;
// Every light is a pass over the frame's pixels: 10^4 point lights took 4.7 s to render, 10^6 over 180 s;
// real scenes hold tens.
constexpr size_t kMaxSceneLights = 4'096;

// Reads typed fields and throws SceneError with the full field path on any mismatch.
class Reader {
 public:
  Reader(const std::string& file, const json& node, std::string path)
      : file_(file), node_(node), path_(std::move(path)) {}

  Reader child(const std::string& key) const {
    if (!node_.is_object()) fail("expected an object");
    if (!node_.contains(key)) fail("missing required key '" + key + "'");
    return Reader(file_, node_.at(key), path_ + "." + key);
  }
  Reader element(size_t i) const { return Reader(file_, node_.at(i), path_ + "[" + std::to_string(i) + "]"); }
  bool has(const std::string& key) const { return node_.is_object() && node_.contains(key); }
  const json& raw() const { return node_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& problem) const { throw SceneError(file_, path_, problem); }

  void expectObject(std::initializer_list<const char*> allowed) const {
    if (!node_.is_object()) fail("expected an object");
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      bool known = false;
      for (const char* key : allowed) known = known || it.key() == key;
      if (!known) {
        std::string list;
        for (const char* key : allowed) list += std::string(list.empty() ? "" : ", ") + key;
        throw SceneError(file_, path_ + "." + it.key(), "unknown key (allowed: " + list + ")");
      }
    }
  }
  size_t arraySize() const {
    if (!node_.is_array()) fail("expected an array");
    return node_.size();
  }
  float number(float minimum = -INFINITY, float maximum = INFINITY) const {
    if (!node_.is_number()) fail("expected a number");
    const double value = node_.get<double>();
    if (!std::isfinite(value) || value < minimum || value > maximum)
      fail("expected a finite number in [" + format(minimum) + ", " + format(maximum) + "], got " + node_.dump());
    return static_cast<float>(value);
  }
  int integer(int minimum, int maximum) const {
    if (!node_.is_number_integer()) fail("expected an integer");
    const long long value = node_.get<long long>();
    if (value < minimum || value > maximum)
      fail("expected an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) + "], got " +
           node_.dump());
    return static_cast<int>(value);
  }
  std::string string() const {
    if (!node_.is_string()) fail("expected a string");
    return node_.get<std::string>();
  }
  bool boolean() const {
    if (!node_.is_boolean()) fail("expected true or false");
    return node_.get<bool>();
  }
  glm::vec3 vec3(float minimum = -1e9f, float maximum = 1e9f) const {
    if (!node_.is_array() || node_.size() != 3) fail("expected an array of 3 numbers");
    return {element(0).number(minimum, maximum), element(1).number(minimum, maximum),
            element(2).number(minimum, maximum)};
  }
  float numberOr(const std::string& key, float fallback, float minimum = -INFINITY, float maximum = INFINITY) const {
    return has(key) ? child(key).number(minimum, maximum) : fallback;
  }
  glm::vec3 vec3Or(const std::string& key, glm::vec3 fallback, float minimum = -1e9f, float maximum = 1e9f) const {
    return has(key) ? child(key).vec3(minimum, maximum) : fallback;
  }

 private:
  static std::string format(float v) {
    std::ostringstream out;
    out << v;
    return out.str();
  }
  const std::string& file_;
  const json& node_;
  std::string path_;
};

// The value a string field names, from its one table of names; an unknown name fails naming the
// field and every allowed one.
template <typename Enum>
Enum namedValue(const Reader& field, const char* what, std::initializer_list<std::pair<const char*, Enum>> names) {
  const std::string name = field.string();
  std::string allowed;
  for (const auto& [candidate, value] : names) {
    if (name == candidate) return value;
    allowed += std::string(allowed.empty() ? "" : ", ") + candidate;
  }
  field.fail("unknown " + std::string(what) + " '" + name + "' (allowed: " + allowed + ")");
  return names.begin()->second;  // fail() throws
}

// A material's maps: "procedural" generates a set, the *_map keys name image files (relative to the
// scene) and replace the generated map of their role.
size_t textureBytes(const MaterialMaps& maps) {
  size_t bytes = 0;
  for (const SharedTextureImage* image : {&maps.albedo, &maps.normal, &maps.specular, &maps.emissive})
    if (*image) bytes += (*image)->rgba.size();
  return bytes;
}

// `budget`: what the scene's textures may still hold (kMaxSceneTextureBytes in all).
MaterialMaps readMaps(const Reader& m, const std::string& baseDirectory, size_t& budget) {
  auto spend = [&budget](const Reader& field, size_t bytes) {
    if (bytes > budget)
      field.fail("the scene's textures would exceed " + std::to_string(kMaxSceneTextureBytes >> 20) + " MiB");
    budget -= bytes;
  };
  MaterialMaps maps;
  if (m.has("procedural")) {
    const Reader p = m.child("procedural");
    p.expectObject({"pattern", "texels", "seed", "glow"});
    ProceduralPattern pattern;
    if (p.has("pattern")) pattern.pattern = p.child("pattern").string();
    if (p.has("texels")) pattern.texels = p.child("texels").integer(16, 2048);
    if (pattern.texels & (pattern.texels - 1)) p.child("texels").fail("expected a power of two");
    if (p.has("seed")) pattern.seed = uint32_t(p.child("seed").integer(0, 1 << 30));
    pattern.glow = p.numberOr("glow", 0.0f, 0.0f, 1.0f);
    // Generating holds ~36 bytes a texel besides the maps' 16: checked before, not after.
    spend(p, size_t(pattern.texels) * size_t(pattern.texels) * 16);
    try {
      maps = generateMaps(pattern);
    } catch (const TextureError& e) {
      p.child("pattern").fail(e.what());
    }
  }
  const std::pair<const char*, SharedTextureImage MaterialMaps::*> files[] = {
      {"albedo_map", &MaterialMaps::albedo},
      {"normal_map", &MaterialMaps::normal},
      {"specular_map", &MaterialMaps::specular},
      {"emissive_map", &MaterialMaps::emissive}};
  for (const auto& [key, role] : files) {
    if (!m.has(key)) continue;
    const std::filesystem::path file = m.child(key).string();
    const std::string resolved =
        file.is_absolute() ? file.string() : (std::filesystem::path(baseDirectory) / file).string();
    try {
      maps.*role = readTextureFile(resolved);
    } catch (const TextureError& e) {
      m.child(key).fail(e.what());
    }
    spend(m.child(key), (maps.*role)->rgba.size());
  }
  maps.uvScale = m.numberOr("uv_scale", 1.0f, 1e-4f, 1e4f);
  return maps;
}

glm::mat4 readTransform(const Reader& r) {
  r.expectObject({"translate", "rotate_deg", "scale"});
  glm::mat4 m(1.0f);
  m = glm::translate(m, r.vec3Or("translate", glm::vec3(0)));
  const glm::vec3 rotation = glm::radians(r.vec3Or("rotate_deg", glm::vec3(0), -3600, 3600));
  m = glm::rotate(m, rotation.y, {0, 1, 0});
  m = glm::rotate(m, rotation.x, {1, 0, 0});
  m = glm::rotate(m, rotation.z, {0, 0, 1});
  if (r.has("scale")) {
    const Reader s = r.child("scale");
    const glm::vec3 scale = s.raw().is_number() ? glm::vec3(s.number(1e-6f, 1e7f)) : s.vec3(1e-6f, 1e7f);
    m = glm::scale(m, scale);
  }
  return m;
}

size_t meshBytes(size_t vertices, size_t indices) { return vertices * sizeof(Vertex) + indices * sizeof(uint32_t); }
size_t meshBytes(const Mesh& mesh) { return meshBytes(mesh.vertices.size(), mesh.indices.size()); }

// The scene's meshes within kMaxSceneGeometryBytes, checked before anything large is generated or read.
class GeometryBudget {
 public:
  // Refuses `field` where `bytes` more would pass the budget.
  void check(const Reader& field, size_t bytes) const {
    if (bytes > kMaxSceneGeometryBytes - spent_)
      field.fail("the scene's meshes would take " + std::to_string((spent_ + bytes) >> 20) +
                 " MiB (vertices and indices, each repeat its own copy, and as much again on the GPU), more than "
                 "the " +
                 std::to_string(kMaxSceneGeometryBytes >> 20) + " MiB budget");
  }
  void spend(const Reader& field, size_t bytes) {
    check(field, bytes);
    spent_ += bytes;
  }

 private:
  size_t spent_ = 0;
};

// A model's bytes on disk, which bound what assimp allocates reading it: the file, and for a .gltf the
// buffer files it names (a "data:" URI is inside the file already).
std::uintmax_t modelFileBytes(const Reader& field, const std::string& path) {
  std::error_code error;
  std::uintmax_t bytes = std::filesystem::file_size(path, error);
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (error || extension != ".gltf" || bytes > kMaxModelFileBytes) return error ? 0 : bytes;
  std::string problem;
  const std::optional<std::string> text = readUserTextFile(path, problem);
  if (!text) return bytes;
  json document;
  try {
    document = parseBoundedJson(*text, path);
  } catch (const SceneError& e) {
    field.fail(e.what());
  }
  if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) return bytes;
  for (const json& buffer : document["buffers"]) {
    if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string()) continue;
    const std::string uri = buffer["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) continue;
    const std::uintmax_t size = std::filesystem::file_size(std::filesystem::path(path).parent_path() / uri, error);
    if (!error) bytes += size;
  }
  return bytes;
}

// "repeat": {"count": n, "offset": [x,y,z]} places n copies, each shifted by offset.
int repeatCount(const Reader& o) {
  if (!o.has("repeat")) return 1;
  const Reader rep = o.child("repeat");
  rep.expectObject({"count", "offset"});
  return rep.child("count").integer(1, 10000);
}

// What an object's generated meshes will take, known before any is built (only the greebled hull can be
// large; a model counts once read, within kMaxModelFileBytes).
size_t plannedGeneratorBytes(const Reader& o) {
  if (!o.has("generator")) return 0;
  const Reader r = o.child("generator");
  if (!r.has("type") || !r.child("type").raw().is_string() || r.child("type").string() != "greebled_hull" ||
      !r.has("greebles"))
    return 0;
  const size_t boxes = 1 + size_t(r.child("greebles").integer(0, 200000));
  return boxes * meshBytes(24, 36) * size_t(repeatCount(o));
}

Mesh readGenerator(const Reader& r) {
  const std::string kind = r.child("type").string();
  if (kind == "box") {
    r.expectObject({"type", "size"});
    return generate::box(r.child("size").vec3(1e-6f, 1e7f));
  }
  if (kind == "plane") {
    r.expectObject({"type", "size"});
    const glm::vec3 size = r.child("size").vec3(1e-6f, 1e7f);
    return generate::plane({size.x, size.z});
  }
  if (kind == "sphere") {
    r.expectObject({"type", "radius", "subdivisions"});
    return generate::sphere(r.child("radius").number(1e-6f, 1e7f),
                            r.has("subdivisions") ? r.child("subdivisions").integer(1, 32) : 4);
  }
  if (kind == "cylinder") {
    r.expectObject({"type", "radius", "length", "segments"});
    return generate::cylinder(r.child("radius").number(1e-6f, 1e7f), r.child("length").number(1e-6f, 1e7f),
                              r.has("segments") ? r.child("segments").integer(3, 256) : 12);
  }
  if (kind == "greebled_hull") {
    r.expectObject({"type", "size", "greebles", "greeble_min", "greeble_max", "normal_noise", "seed"});
    generate::GreebledHull p;
    p.size = r.child("size").vec3(1e-3f, 1e7f);
    if (r.has("greebles")) p.greebles = r.child("greebles").integer(0, 200000);
    p.greebleMin = r.numberOr("greeble_min", p.greebleMin, 1e-6f, 1e6f);
    p.greebleMax = r.numberOr("greeble_max", p.greebleMax, p.greebleMin, 1e6f);
    p.normalNoise = r.numberOr("normal_noise", p.normalNoise, 0.0f, 1.5f);
    if (r.has("seed")) p.seed = static_cast<uint32_t>(r.child("seed").integer(0, 1 << 30));
    return generate::greebledHull(p);
  }
  r.child("type").fail("unknown generator '" + kind + "' (allowed: box, plane, sphere, cylinder, greebled_hull)");
}

Camera readCamera(const Reader& r) {
  r.expectObject({"position", "target", "up", "fov_y_deg", "near", "far"});
  Camera c;
  c.position = r.child("position").vec3();
  c.target = r.child("target").vec3();
  c.up = r.vec3Or("up", c.up);
  c.fovYDegrees = r.numberOr("fov_y_deg", c.fovYDegrees, 1.0f, 170.0f);
  c.nearPlane = r.numberOr("near", c.nearPlane, 1e-4f, 1e3f);
  c.farPlane = r.numberOr("far", c.farPlane, c.nearPlane * 2.0f, 1e7f);
  if (glm::length(c.target - c.position) <= 0.0f) r.child("target").fail("target equals position");
  return c;
}

CameraPath readCameraPath(const Reader& p) {
  p.expectObject({"fps", "keys", "comment"});
  CameraPath path;
  path.framesPerSecond = p.numberOr("fps", path.framesPerSecond, 1.0f, 1000.0f);
  const Reader keys = p.child("keys");
  for (size_t i = 0; i < keys.arraySize(); ++i) {
    const Reader k = keys.element(i);
    k.expectObject({"t", "position", "target"});
    CameraKey key{k.child("t").number(0.0f, 1e6f), k.child("position").vec3(), k.child("target").vec3()};
    if (!path.keys.empty() && key.time <= path.keys.back().time) k.child("t").fail("key times must increase");
    path.keys.push_back(key);
  }
  return path;
}

}  // namespace

SceneError::SceneError(const std::string& file, const std::string& field, const std::string& problem)
    : std::runtime_error(file + ": " + field + ": " + problem) {}

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

Camera fitCamera(const std::vector<Object>& objects, const Camera& base, glm::vec3 direction) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Object& object : objects)
    for (const Vertex& v : object.mesh.vertices) {
      const glm::vec3 p = glm::vec3(object.transform * glm::vec4(v.position, 1.0f));
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
  Camera camera = base;
  if (lo.x > hi.x) return camera;  // nothing to frame
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  // The sphere fits the vertical fov (the narrower one at landscape sizes), with a 5 % margin.
  const float distance = 1.05f * radius / std::sin(0.5f * glm::radians(camera.fovYDegrees));
  if (glm::length(direction) <= 0.0f) direction = glm::vec3(0, 0, -1);
  direction = glm::normalize(direction);
  if (std::fabs(glm::dot(direction, glm::normalize(camera.up))) > 0.99f) camera.up = glm::vec3(0, 0, -1);
  camera.target = centre;
  camera.position = centre - direction * distance;
  camera.nearPlane = std::clamp(0.5f * (distance - radius), 1e-4f, 0.1f);
  camera.farPlane = std::max(camera.farPlane, std::min(4.0f * (distance + radius), 1e7f));
  return camera;
}

glm::mat4 Camera::projection(int width, int height, glm::vec2 jitterPixels) const {
  glm::mat4 p = glm::perspective(glm::radians(fovYDegrees), float(width) / float(height), nearPlane, farPlane);
  // A clip-space translation of 2/size per pixel shifts the raster by whole pixels.
  p[2][0] += 2.0f * jitterPixels.x / float(width);
  p[2][1] += 2.0f * jitterPixels.y / float(height);
  return p;
}

int CameraPath::frameCount() const {
  if (keys.size() < 2) return 1;
  return static_cast<int>(std::floor((keys.back().time - keys.front().time) * framesPerSecond)) + 1;
}

Camera CameraPath::at(const Camera& base, int frame) const {
  Camera camera = base;
  camera.time = frame / framesPerSecond;
  if (keys.empty()) return camera;
  const float t = keys.front().time + frame / framesPerSecond;
  size_t i = 0;
  while (i + 1 < keys.size() && keys[i + 1].time <= t) ++i;
  if (i + 1 >= keys.size()) {
    camera.position = keys.back().position;
    camera.target = keys.back().target;
    return camera;
  }
  const float span = keys[i + 1].time - keys[i].time;
  const float s = span > 0 ? glm::clamp((t - keys[i].time) / span, 0.0f, 1.0f) : 0.0f;
  const float smooth = s * s * (3.0f - 2.0f * s);  // eases in and out of each key
  camera.position = glm::mix(keys[i].position, keys[i + 1].position, smooth);
  camera.target = glm::mix(keys[i].target, keys[i + 1].target, smooth);
  return camera;
}

glm::mat4 Object::transformAt(float time) const { return glm::translate(glm::mat4(1.0f), velocity * time) * transform; }

bool Scene::objectsMove() const {
  return std::any_of(objects.begin(), objects.end(), [](const Object& o) { return o.velocity != glm::vec3(0.0f); });
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Object& o : objects) n += o.mesh.triangleCount();
  return n;
}

namespace {

// "materials" (optional when every object is a model that keeps its own), within the texture budget.
void readMaterials(const Reader& root, const std::string& fileName, const std::string& baseDirectory, Scene& scene,
                   size_t& textureBudget) {
  // "materials" may be left out when every object is a model that keeps its own.
  static const json kNoMaterials = json::array();
  const Reader materials =
      root.has("materials") ? root.child("materials") : Reader(fileName, kNoMaterials, "$.materials");
  for (size_t i = 0; i < materials.arraySize(); ++i) {
    const Reader m = materials.element(i);
    m.expectObject({"name", "albedo", "specular", "gloss", "emissive", "procedural", "albedo_map", "normal_map",
                    "specular_map", "emissive_map", "uv_scale"});
    Material material;
    material.name = m.child("name").string();
    material.albedo = m.vec3Or("albedo", material.albedo, 0.0f, 1.0f);
    material.specular = m.vec3Or("specular", material.specular, 0.0f, 1.0f);
    material.gloss = m.numberOr("gloss", material.gloss, 0.0f, 1.0f);
    material.emissive = m.vec3Or("emissive", material.emissive, 0.0f, 1e4f);
    material.maps = readMaps(m, baseDirectory, textureBudget);
    scene.materials.push_back(material);
  }
}

// Object `i` of "objects": its mesh (generated, or a model, split into its parts where it keeps its own
// materials) and its repeats, appended to the scene within its object, triangle and texture budgets.
void readObject(const Reader& o, size_t i, const std::string& baseDirectory, Scene& scene, size_t& textureBudget,
                GeometryBudget& geometryBudget) {
  o.expectObject({"name", "generator", "model", "material", "transform", "velocity", "repeat"});
  Object object;
  object.name = o.has("name") ? o.child("name").string() : "object" + std::to_string(i);
  if (o.has("generator") == o.has("model")) o.fail("needs exactly one of 'generator' or 'model'");
  const int count = repeatCount(o);
  glm::vec3 offset(0);
  if (o.has("repeat")) offset = o.child("repeat").child("offset").vec3();
  std::vector<ModelPart> parts;  // a model's own materials, unless "material" overrides them
  if (o.has("generator")) {
    object.mesh = readGenerator(o.child("generator"));
    if (!o.has("material")) o.fail("missing required key 'material'");
  } else {
    const std::filesystem::path model = o.child("model").string();
    const std::string resolved =
        model.is_absolute() ? model.string() : (std::filesystem::path(baseDirectory) / model).string();
    // Only regular files: a path like /dev/zero would never end.
    std::error_code error;
    if (!std::filesystem::is_regular_file(resolved, error))
      o.child("model").fail("'" + resolved + "' is not a regular file");
    if (const std::uintmax_t bytes = modelFileBytes(o.child("model"), resolved); bytes > kMaxModelFileBytes)
      o.child("model").fail("'" + resolved + "' is " + std::to_string(bytes >> 20) +
                            " MiB with the buffers it names, more than the " +
                            std::to_string(kMaxModelFileBytes >> 20) + " MiB a model may be");
    try {
      // A "material" override replaces the model's own: its textures are not read (nor missing ones refused).
      parts = loadModel(resolved, nullptr, o.has("material") ? ModelTextures::Skip : ModelTextures::Read);
    } catch (const ModelLoadError& e) {
      o.child("model").fail(e.what());
    }
    if (o.has("material")) object.mesh = mergeParts(parts), parts.clear();
  }
  if (o.has("material")) {
    const std::string materialName = o.child("material").string();
    object.material = -1;
    for (size_t m = 0; m < scene.materials.size(); ++m)
      if (scene.materials[m].name == materialName) object.material = static_cast<int>(m);
    if (object.material < 0) o.child("material").fail("no material named '" + materialName + "'");
  }
  if (o.has("transform")) object.transform = readTransform(o.child("transform"));
  if (o.has("velocity")) object.velocity = o.child("velocity").vec3();
  // Without "material", each of the model's materials becomes a scene material ("<object>/<name>") and
  // each part an object of its own.
  std::vector<Object> pieces;
  for (ModelPart& part : parts) {
    const size_t bytes = textureBytes(part.maps);
    if (bytes > textureBudget)
      o.child("model").fail("the scene's textures would exceed " + std::to_string(kMaxSceneTextureBytes >> 20) +
                            " MiB");
    textureBudget -= bytes;
    Material material;
    material.name = object.name + "/" + part.materialName;
    material.albedo = part.albedo;
    material.emissive = part.emissive;
    material.maps = part.maps;
    scene.materials.push_back(material);
    Object piece = object;
    piece.mesh = std::move(part.mesh);
    piece.material = int(scene.materials.size() - 1);
    pieces.push_back(std::move(piece));
  }
  if (parts.empty()) pieces.push_back(std::move(object));
  if (scene.objects.size() + pieces.size() * size_t(count) > kMaxSceneObjects)
    o.fail("the scene exceeds " + std::to_string(kMaxSceneObjects) +
           " objects (with its repeats and parts this one brings it to " +
           std::to_string(scene.objects.size() + pieces.size() * size_t(count)) + ")");
  for (const Object& piece : pieces) {
    geometryBudget.spend(o, meshBytes(piece.mesh) * size_t(count));
    for (int c = 0; c < count; ++c) {
      Object copy = piece;
      copy.transform = glm::translate(glm::mat4(1.0f), offset * float(c)) * piece.transform;
      if (count > 1) copy.name += "#" + std::to_string(c);
      scene.objects.push_back(std::move(copy));
    }
  }
}

std::vector<Light> readLights(const Reader& lights) {
  std::vector<Light> out;
  for (size_t i = 0; i < lights.arraySize(); ++i) {
    const Reader l = lights.element(i);
    l.expectObject({"type", "color", "intensity", "position", "end", "direction", "radius"});
    Light light;
    const std::string type = l.child("type").string();
    light.color = l.vec3Or("color", light.color, 0.0f, 1e4f);
    light.intensity = l.numberOr("intensity", light.intensity, 0.0f, 1e9f);
    if (type == "directional") {
      light.type = LightType::Directional;
      light.direction = l.child("direction").vec3();
      if (glm::length(light.direction) <= 0.0f) l.child("direction").fail("zero-length direction");
      light.direction = glm::normalize(light.direction);
    } else if (type == "point" || type == "tube") {
      light.type = type == "point" ? LightType::Point : LightType::Tube;
      light.position = l.child("position").vec3();
      light.end = light.type == LightType::Tube ? l.child("end").vec3() : light.position;
      light.radius = l.child("radius").number(1e-4f, 1e7f);
    } else {
      l.child("type").fail("unknown light type '" + type + "' (allowed: directional, point, tube)");
    }
    out.push_back(light);
  }
  return out;
}

// "camera_path": inline, or the name of a file `retroaa record` wrote (relative to the scene file). A
// missing file is an error only where `requireCameraPath`; otherwise the scene has no path.
CameraPath readScenePath(const Reader& p, const std::string& baseDirectory, bool requireCameraPath) {
  if (!p.raw().is_string()) return readCameraPath(p);
  const std::filesystem::path file = p.string();
  const std::string resolved =
      file.is_absolute() ? file.string() : (std::filesystem::path(baseDirectory) / file).string();
  std::string problem;
  const std::optional<std::string> text = readUserTextFile(resolved, problem);
  if (!text && !requireCameraPath) return CameraPath{};
  if (!text) p.fail("cannot open camera path file '" + resolved + "': " + problem);
  // Errors inside the path file name both: the scene's field and the path file's own field.
  try {
    const json pathDocument = parseBoundedJson(*text, resolved);
    return readCameraPath(Reader(resolved, pathDocument, "$"));
  } catch (const SceneError& e) {
    p.fail(e.what());
  }
  return CameraPath{};  // not reached: fail() throws
}

}  // namespace

Scene parseScene(const std::string& jsonText, const std::string& fileName, const std::string& baseDirectory,
                 bool requireCameraPath) {
  const json document =
      parseBoundedJson(jsonText, fileName, {{"objects", kMaxSceneObjects}, {"lights", kMaxSceneLights}});
  const Reader root(fileName, document, "$");
  root.expectObject({"name", "camera", "camera_path", "materials", "objects", "lights", "ambient", "sky_color",
                     "star_density", "exposure", "shading", "depth_buffer", "position_depth", "object_motion",
                     "comment"});
  Scene scene;
  scene.name = root.has("name") ? root.child("name").string() : fileName;
  if (!root.has("camera")) root.fail("missing required key 'camera'");
  // "fit": frame whatever the objects turn out to be (set once they are loaded).
  const bool fitToObjects = root.child("camera").raw().is_string();
  if (fitToObjects && root.child("camera").string() != "fit")
    root.child("camera").fail("expected a camera object or \"fit\"");
  if (!fitToObjects) scene.camera = readCamera(root.child("camera"));
  scene.ambient = root.vec3Or("ambient", scene.ambient, 0.0f, 1e4f);
  scene.skyColor = root.vec3Or("sky_color", scene.skyColor, 0.0f, 1e4f);
  if (root.has("object_motion"))
    scene.objectMotion = namedValue<Scene::ObjectMotion>(root.child("object_motion"), "object motion",
                                                         {{"velocity", Scene::ObjectMotion::Velocity},
                                                          {"boxes", Scene::ObjectMotion::Boxes},
                                                          {"camera", Scene::ObjectMotion::Camera}});
  scene.starDensity = root.numberOr("star_density", scene.starDensity, 0.0f, 10.0f);
  scene.exposure = root.numberOr("exposure", scene.exposure, 1e-4f, 1e4f);
  scene.shading = root.has("shading") ? namedValue<ShadingModel>(
                                            root.child("shading"), "shading model",
                                            {{"blinn-phong", ShadingModel::BlinnPhong}, {"ggx", ShadingModel::GGX}})
                                      : scene.shading;
  scene.depthBuffer = root.has("depth_buffer") ? namedValue<DepthBuffer>(root.child("depth_buffer"), "depth buffer",
                                                                         {{"logarithmic", DepthBuffer::Logarithmic},
                                                                          {"perspective", DepthBuffer::Perspective}})
                                               : scene.depthBuffer;
  if (root.has("position_depth")) {
    scene.positionDepth = namedValue<PositionDepth>(
        root.child("position_depth"), "position depth",
        {{"log-above-knee", PositionDepth::LogAboveKnee}, {"fso-compressed", PositionDepth::FsoCompressed}});
    // FSO's far segment divides by (100 000 m − GLOBAL_FAR_Z), the far plane.
    if (scene.positionDepth == PositionDepth::FsoCompressed && !(scene.camera.farPlane > 100000.0f))
      root.child("position_depth").fail("fso-compressed needs a camera far plane beyond 100000 m (FSO's GLOBAL_FAR_Z)");
  }
  size_t textureBudget = kMaxSceneTextureBytes;
  readMaterials(root, fileName, baseDirectory, scene, textureBudget);

  if (!root.has("objects")) root.fail("missing required key 'objects'");
  const Reader objects = root.child("objects");
  if (objects.arraySize() > kMaxSceneObjects)
    objects.fail("has " + std::to_string(objects.arraySize()) + " objects (at most " +
                 std::to_string(kMaxSceneObjects) + ")");
  GeometryBudget geometryBudget;
  size_t plannedBytes = 0;
  for (size_t i = 0; i < objects.arraySize(); ++i) plannedBytes += plannedGeneratorBytes(objects.element(i));
  geometryBudget.check(objects, plannedBytes);
  for (size_t i = 0; i < objects.arraySize(); ++i)
    readObject(objects.element(i), i, baseDirectory, scene, textureBudget, geometryBudget);

  if (fitToObjects) {
    if (scene.objects.empty()) root.child("camera").fail("\"fit\" needs at least one object to frame");
    scene.camera = fitCamera(scene.objects, scene.camera, glm::vec3(-0.5f, -0.3f, -0.8f));  // a three-quarter view
  }
  if (root.has("lights")) scene.lights = readLights(root.child("lights"));
  if (root.has("camera_path")) scene.path = readScenePath(root.child("camera_path"), baseDirectory, requireCameraPath);
  return scene;
}

std::optional<std::string> readUserTextFile(const std::string& path, std::string& problem) {
  constexpr std::uintmax_t kMaxTextFileBytes = 64u << 20;
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) return problem = "it does not exist", std::nullopt;
  if (std::filesystem::is_directory(status)) return problem = "it is a directory", std::nullopt;
  if (!std::filesystem::is_regular_file(status)) return problem = "it is not a regular file", std::nullopt;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (!error && bytes > kMaxTextFileBytes)
    return problem = "it is " + std::to_string(bytes) + " bytes, more than the " +
                     std::to_string(kMaxTextFileBytes >> 20) + " MiB allowed",
           std::nullopt;
  std::ifstream in(path);
  if (!in) return problem = "it cannot be read", std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Scene loadScene(const std::string& pathOrDefault, bool requireCameraPath) {
  if (pathOrDefault.empty() || pathOrDefault == "default") {
    const auto& files = embeddedFiles();
    return parseScene(files.at("scenes/demo.json"), "default", ".");
  }
  std::string problem;
  const std::optional<std::string> text = readUserTextFile(pathOrDefault, problem);
  if (!text) throw SceneError(pathOrDefault, "(file)", "cannot open scene file: " + problem);
  return parseScene(*text, pathOrDefault, std::filesystem::path(pathOrDefault).parent_path().string(),
                    requireCameraPath);
}

}  // namespace host
