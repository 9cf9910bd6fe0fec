// What the tools need of a host engine, whichever host it is: render a frame, read what it displays
// and the linear radiance behind it. renderer.h is the FreeSpace Open-shaped host, second_renderer.h
// a deferred renderer shaped unlike it; each has its own seams for an AA module (frame_hooks.h,
// SecondSeams) and its patch beside it (engine-patch/fso-host/, engine-patch/second-host/).
#pragma once

#include "material_textures.h"
#include "scene.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace host {

// The frame's camera as both engines hand it to an AA module (its resolve's closeness test, a history's
// reprojection), per frame.
struct FrameView {
  float verticalFovRadians = 1.0f;  // the projection's (FreeSpace Open's Proj_fov)
  int width = 0, height = 0;
  float nearPlane = 0.1f, farPlane = 1e6f;  // metres
  glm::mat4 view{1.0f};                     // world to view
  glm::mat4 projection{1.0f};               // view to clip, without an AA module's jitter
  // Objects that move on their own, as boxes (the cube [-1, 1]³ onto each, world space) now and a frame
  // ago: what an engine without a velocity output can say of its moving objects (Scene::ObjectMotion::Boxes).
  struct MovingBox {
    glm::mat4 now{1.0f}, before{1.0f};
  };
  std::vector<MovingBox> movingBoxes;
};

// GPU time of the host's passes for the last frame (timer queries), in milliseconds.
struct HostTimings {
  double modelPassMs = 0;       // the host's own geometry: sky and models into the model-pass target
  double afterModelPassMs = 0;  // the hooks after it: the plugin's resolve, a prepass of the models
  double lightingMs = 0, tonemapMs = 0, frameMs = 0;
};

// The timestamps that split one frame into HostTimings' stages. Reading them waits for the GPU: only
// while Engine::measureTime is on (tools).
class StageTimestamps {
 public:
  enum Stage { FrameStart, ModelPassEnd, HooksEnd, LightingEnd, FrameEnd, kStages };
  explicit StageTimestamps(bool on) : on_(on) {
    if (on_) glGenQueries(kStages, queries_);
  }
  void stamp(Stage stage) {
    if (on_) glQueryCounter(queries_[stage], GL_TIMESTAMP);
  }
  // After FrameEnd: fills `timings` and frees the queries (nothing while off).
  void readInto(HostTimings& timings) {
    if (!on_) return;
    GLuint64 t[kStages];
    for (int i = 0; i < kStages; ++i) glGetQueryObjectui64v(queries_[i], GL_QUERY_RESULT, &t[i]);
    glDeleteQueries(kStages, queries_);
    on_ = false;
    timings.modelPassMs = (t[ModelPassEnd] - t[FrameStart]) * 1e-6;
    timings.afterModelPassMs = (t[HooksEnd] - t[ModelPassEnd]) * 1e-6;
    timings.lightingMs = (t[LightingEnd] - t[HooksEnd]) * 1e-6;
    timings.tonemapMs = (t[FrameEnd] - t[LightingEnd]) * 1e-6;
    timings.frameMs = (t[FrameEnd] - t[FrameStart]) * 1e-6;
  }

 private:
  bool on_;
  GLuint queries_[kStages] = {};
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual void resize(int width, int height) = 0;
  // Renders one frame into the display target; `jitterPixels` shifts the image (ground truth).
  virtual void renderFrame(const Camera& camera, glm::vec2 jitterPixels = glm::vec2(0)) = 0;
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual const Scene& scene() const = 0;
  virtual GLuint displayFramebuffer() const = 0;
  // The display as top-down RGBA8 (sRGB-encoded values), and the frame's linear radiance as top-down
  // RGBA32F: what the ground truth averages.
  virtual std::vector<uint8_t> readDisplay() const = 0;
  virtual std::vector<float> readLight() const = 0;
  // For the ground truth (ground_truth.h): the texture that reads as the frame's linear radiance; how the
  // display encodes a radiance (accumulate.frag's #defines: none for FSO's tonemap at exposure(),
  // DISPLAY_CLAMP for radiance clamped to [0, 1]); and the pass that shows an averaged radiance.
  virtual GLuint radianceTexture() const = 0;
  virtual std::string groundTruthDefines() const = 0;
  virtual float exposure() const = 0;
  virtual void present(GLuint radianceTexture) = 0;
  // While true, frames take the host's stock path, whatever AA seams are installed (the ground truth).
  virtual void setStockPath(bool stock) = 0;

  bool measureTime = false;  // timer queries around each pass (waits for the GPU)
  const HostTimings& timings() const { return timings_; }
  // The material textures' LOD bias (0 by default); the ground truth sets −log2 of its samples per axis.
  // An AA module's own bias (FrameHooks::textureLodBias) adds to it in each frame.
  void setTextureLodBias(float bias) {
    textureLodBias_ = bias;
    materialTextures_->setLodBias(bias);
  }
  void setMaterialMapsOn(bool on) { materialTextures_->setMapsOn(on); }
  // The background's own detail (the FSO-shaped host's stars): whether it has any, and drawing it or only
  // the plain sky beneath, for a ground truth that tells the background's edges from the models'.
  virtual bool hasBackgroundDetail() const { return false; }
  void setBackgroundDetailOn(bool on) { backgroundDetailOn_ = on; }
  const MaterialTextures& materialTextures() const { return *materialTextures_; }

 protected:
  void applyTextureLodBias(float moduleBias) { materialTextures_->setLodBias(textureLodBias_ + moduleBias); }
  float textureLodBias_ = 0.0f;
  bool backgroundDetailOn_ = true;
  HostTimings timings_;
  std::unique_ptr<MaterialTextures> materialTextures_;  // created with the scene's meshes
};

}  // namespace host
