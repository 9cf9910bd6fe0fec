// The host engine's stock deferred pipeline, shaped like FreeSpace Open's OpenGL backend:
// G-buffer (FSO's attachments) → lighting (ambient + directional, then point and tube light volumes
// additively, then emissive) → tonemap to 8-bit sRGB.
#pragma once

#include "engine.h"
#include "frame_hooks.h"
#include "gl_objects.h"
#include "scene.h"

#include <cstdint>
#include <vector>

namespace host {

class Renderer : public Engine {
 public:
  Renderer(const Scene& scene, int width, int height);
  ~Renderer() override;
  // Bytes a pixel's G-buffer takes (its attachments and depth-stencil) for `scene`: what an AA module's
  // multisampled mirror of it takes a sample, known before any target exists.
  static uint64_t gbufferBytesPerSample(const Scene& scene);
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void resize(int width, int height) override;
  void setHooks(FrameHooks* hooks);  // nullptr: the stock path
  FrameHooks* hooks() const { return hooks_; }
  // Renders one frame; the display target then holds the 8-bit result and the light target the HDR.
  void renderFrame(const Camera& camera, glm::vec2 jitterPixels = glm::vec2(0)) override;
  // The host's tonemap pass from any HDR texture into its display target.
  void tonemap(GLuint hdrTexture);
  // The host's lighting pass alone, from whatever its G-buffer holds, into `target` (tools and tests).
  void lightGBuffer(const Camera& camera, GLuint target);

  const HostTargets& targets() const { return targets_; }
  const Scene& scene() const override { return scene_; }
  int width() const override { return targets_.width; }
  int height() const override { return targets_.height; }
  GLuint displayFramebuffer() const override { return targets_.displayFramebuffer; }
  float exposure() const override { return scene_.exposure; }
  GLuint radianceTexture() const override { return targets_.lightTexture; }
  bool hasBackgroundDetail() const override { return scene_.starDensity > 0.0f; }
  std::string groundTruthDefines() const override { return ""; }
  void present(GLuint radiance) override { tonemap(radiance); }
  void setStockPath(bool stock) override;

  // Reads the display target as top-down RGBA8 and the light target as top-down RGBA32F.
  std::vector<uint8_t> readDisplay() const override;
  std::vector<float> readLight() const override;

 private:
  void createTargets(int width, int height);
  void lightingPass(GLuint target, const Camera& camera, const glm::mat4& projection);
  void drawBackground(const glm::mat4& view, const glm::mat4& projection, glm::vec2 viewportSize);
  void drawPrepass(GLuint target, const Camera& camera, const glm::mat4& projection);
  void drawModels(const Camera& camera, const glm::mat4& projection);

  const Scene& scene_;
  FrameHooks stockHooks_;
  FrameHooks* hooks_ = &stockHooks_;
  FrameHooks* suspendedHooks_ = nullptr;  // the installed hooks while setStockPath(true)
  HostTargets targets_;
  Texture color_, position_, normal_, specular_, emissive_, depthStencil_, light_, display_, velocity_;
  // This frame's and the previous frame's unjittered view-projection and scene time, for the velocity
  // attachment (the first frame has no previous one).
  struct Motion {
    glm::mat4 current{1.0f}, previous{1.0f};
    float currentTime = 0, previousTime = 0;
  } motion_;
  bool hasPrevious_ = false;
  // Scene::ObjectMotion::Boxes: a box around each object that moves, now and at the previous frame's time.
  std::vector<FrameView::MovingBox> movingBoxes() const;
  int attachmentCount() const { return targets_.velocity ? 6 : 5; }
  Framebuffer gbufferFramebuffer_, lightFramebuffer_, displayFramebuffer_;
  Program modelProgram_, backgroundProgram_, ambientProgram_, pointProgram_, emissiveProgram_, tonemapProgram_;
  std::vector<GpuMesh> meshes_;
  GpuMesh sphereVolume_, boxVolume_;
  VertexArray emptyVertexArray_;
};

}  // namespace host
