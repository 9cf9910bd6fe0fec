// The host engine's stock deferred pipeline, shaped like FreeSpace Open's OpenGL backend:
// G-buffer (FSO's attachments) → lighting (ambient + directional, then point and tube light volumes
// additively, then emissive) → tonemap to 8-bit sRGB.
#pragma once

#include "frame_hooks.h"
#include "gl_objects.h"
#include "scene.h"

#include <cstdint>
#include <vector>

namespace host {

// GPU time of the host's passes for the last frame (timer queries), in milliseconds.
struct HostTimings {
  double modelPassMs = 0;       // the host's own geometry: sky and models into the model-pass target
  double afterModelPassMs = 0;  // the hooks after it: the plugin's resolve, a prepass of the models
  double lightingMs = 0, tonemapMs = 0, frameMs = 0;
};

class Renderer {
 public:
  Renderer(const Scene& scene, int width, int height);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void resize(int width, int height);
  void setHooks(FrameHooks* hooks);  // nullptr: the stock path
  FrameHooks* hooks() const { return hooks_; }
  // Renders one frame; the display target then holds the 8-bit result and the light target the HDR.
  void renderFrame(const Camera& camera, glm::vec2 jitterPixels = glm::vec2(0));
  // The host's tonemap pass from any HDR texture into its display target.
  void tonemap(GLuint hdrTexture);
  // The host's lighting pass alone, from whatever its G-buffer holds, into `target` (tools and tests).
  void lightGBuffer(const Camera& camera, GLuint target);

  const HostTargets& targets() const { return targets_; }
  const Scene& scene() const { return scene_; }
  int width() const { return targets_.width; }
  int height() const { return targets_.height; }
  bool measureTime = false;  // timer queries around each pass (waits for the GPU)
  const HostTimings& timings() const { return timings_; }
  float exposure() const { return scene_.exposure; }

  // Reads the display target as top-down RGBA8 and the light target as top-down RGBA32F.
  std::vector<uint8_t> readDisplay() const;
  std::vector<float> readLight() const;

 private:
  struct GpuMesh {
    VertexArray vertexArray;
    Buffer vertices, indices;
    GLsizei indexCount = 0;
  };
  GpuMesh upload(const Mesh& mesh) const;
  void createTargets(int width, int height);
  void lightingPass(GLuint target, const Camera& camera, const glm::mat4& projection);
  void drawModels(const Camera& camera, const glm::mat4& projection);

  const Scene& scene_;
  FrameHooks stockHooks_;
  FrameHooks* hooks_ = &stockHooks_;
  HostTargets targets_;
  Texture color_, position_, normal_, specular_, emissive_, depthStencil_, light_, display_;
  Framebuffer gbufferFramebuffer_, lightFramebuffer_, displayFramebuffer_;
  Program modelProgram_, backgroundProgram_, ambientProgram_, pointProgram_, emissiveProgram_,
      tonemapProgram_;
  std::vector<GpuMesh> meshes_;
  GpuMesh sphereVolume_, boxVolume_;
  VertexArray emptyVertexArray_;
  HostTimings timings_;
};

}  // namespace host
