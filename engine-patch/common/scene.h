// Scene description for the host engine: JSON files of models (procedural or loaded), materials,
// lights, camera and a recorded camera path. See docs/scenes.md for the format.
#pragma once

#include "mesh.h"

#include <glm/glm.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace host {

struct Camera {
  glm::vec3 position{0, 0, 5};
  glm::vec3 target{0, 0, 0};
  glm::vec3 up{0, 1, 0};
  float fovYDegrees = 50.0f;
  float nearPlane = 0.1f;   // metres
  float farPlane = 2.0e6f;  // metres
  float time = 0;           // seconds into the scene: where objects that move are (Object::velocity)

  glm::mat4 view() const;
  // `jitterPixels` shifts the image by a sub-pixel offset (ground-truth supersampling).
  glm::mat4 projection(int width, int height, glm::vec2 jitterPixels = glm::vec2(0)) const;
};

struct CameraKey {
  float time = 0;  // seconds
  glm::vec3 position;
  glm::vec3 target;
};

// Played back with a fixed time step, never the wall clock: frame i is at time i / fps.
struct CameraPath {
  std::vector<CameraKey> keys;
  float framesPerSecond = 30.0f;
  int frameCount() const;
  Camera at(const Camera& base, int frame) const;
};

struct Material {
  std::string name;
  glm::vec3 albedo{0.5f};
  glm::vec3 specular{0.04f};
  float gloss = 0.5f;  // 0 rough … 1 mirror-like
  glm::vec3 emissive{0.0f};
  // Maps multiply the constants above (docs/scenes.md); none: the constants alone.
  MaterialMaps maps;
};

struct Object {
  std::string name;
  Mesh mesh;
  int material = 0;
  glm::mat4 transform{1.0f};  // at time 0
  glm::vec3 velocity{0.0f};   // m/s in world space: an object that moves on its own (not the camera)
  glm::mat4 transformAt(float time) const;
};

enum class LightType { Directional, Point, Tube };

struct Light {
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  glm::vec3 position{0};          // point; tube start
  glm::vec3 end{0};               // tube end
  glm::vec3 direction{0, -1, 0};  // directional: the direction light travels
  float radius = 10.0f;           // point and tube: distance at which the light reaches zero
};

enum class ShadingModel { BlinnPhong, GGX };

// How the host fills its D24 depth buffer: logarithmic (written by the model shader, for huge depth
// ranges) or the rasteriser's own perspective depth (FreeSpace Open's; interpolated per sample).
enum class DepthBuffer { Logarithmic, Perspective };

// How the host stores view depth in its position attachment's z: this repository's identity-then-log
// encoding (depth_codec.h), or FreeSpace Open's current compressed view z (fso_z, z-compress.sdr).
enum class PositionDepth { LogAboveKnee, FsoCompressed };

struct Scene {
  std::string name;
  Camera camera;
  CameraPath path;
  std::vector<Material> materials;
  std::vector<Object> objects;
  std::vector<Light> lights;
  glm::vec3 ambient{0.02f};
  glm::vec3 skyColor{0.01f, 0.012f, 0.03f};
  float starDensity = 1.0f;
  float exposure = 1.0f;
  ShadingModel shading = ShadingModel::BlinnPhong;
  DepthBuffer depthBuffer = DepthBuffer::Logarithmic;
  PositionDepth positionDepth = PositionDepth::LogAboveKnee;
  // How the FSO-shaped host tells a history of the objects that move on their own ("object_motion"):
  // its model pass writes each pixel's screen motion (a velocity attachment), it hands a box around each
  // object now and a frame ago (FrameInfo::movingObjects, an engine without a velocity output), or neither
  // (the camera alone).
  enum class ObjectMotion { Velocity, Boxes, Camera };
  ObjectMotion objectMotion = ObjectMotion::Velocity;
  bool objectsMove() const;
  size_t triangleCount() const;
};

// A camera looking along `direction` (towards the models) that frames every object's bounds, as loaded
// and transformed: aimed at the bounds' centre, far enough back that their bounding sphere fits the
// vertical field of view of `base` (whose fov, up and far plane it keeps; near follows the distance).
Camera fitCamera(const std::vector<Object>& objects, const Camera& base, glm::vec3 direction);

// A malformed scene: names the file and the field (JSON pointer-like path) and what was expected.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& field, const std::string& problem);
};

// "default" (or "") loads the built-in demo scene of hard cases. With `requireCameraPath` false, a
// camera path file that does not exist yet is no error (`retroaa record` is about to write it).
Scene loadScene(const std::string& pathOrDefault, bool requireCameraPath = true);

// A text file a user points us at (scene, camera path, script, cache, golden): a regular file of at
// most 64 MiB, read whole; otherwise nothing, and `problem` says why ("it is a directory", "it is not a
// regular file", its size...). /dev/zero, a FIFO or a directory would otherwise hang or read as empty.
std::optional<std::string> readUserTextFile(const std::string& path, std::string& problem);
Scene parseScene(const std::string& jsonText, const std::string& fileName, const std::string& baseDirectory,
                 bool requireCameraPath = true);

}  // namespace host
