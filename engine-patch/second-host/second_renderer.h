// A second host, deliberately unlike the FreeSpace Open-shaped one (renderer.h), to prove retroaa in a
// deferred renderer it was not written beside: no position target (positions are rebuilt from the
// depth buffer and the projection), world-space normals octahedrally encoded in an RG16F target,
// albedo + specular intensity in one RGBA8 target, a GL_DEPTH_COMPONENT32F depth buffer with reversed-Z
// (glClipControl zero-to-one, cleared to 0, GL_GREATER), background marked by far depth only, lighting
// as one full-screen pass plus additive light volumes straight into its sRGB display (radiance clamped,
// no tonemap), then a forward pass: emissive objects drawn after lighting, depth-tested against the
// scene. It knows nothing of retroaa; second_host_patch.cpp beside it is the only code that does.
#pragma once

#include "engine.h"
#include "gl_objects.h"
#include "scene.h"

#include <functional>

namespace host {

struct SecondTargets {
  int width = 0, height = 0;
  GLuint gbufferFramebuffer = 0;               // normal (location 0) + albedoSpecular (location 1) + depth
  GLuint normal = 0, albedoSpecular = 0;       // RG16F octahedral world normal; RGBA8 albedo, specular in a
  GLuint depth = 0;                            // GL_DEPTH_COMPONENT32F, reversed-Z
  GLuint displayFramebuffer = 0, display = 0;  // GL_SRGB8_ALPHA8 + the same depth (forward pass)
  GLuint worldPosition = 0;                    // RGBA32F world position at location 2, when asked for (0: none)
};

// Where an AA module may step in. The stock implementation is the host's own single-sample path.
class SecondSeams {
 public:
  virtual ~SecondSeams() = default;
  virtual void targetsCreated(const SecondTargets&) {}
  // The framebuffer the geometry pass clears and draws into (same draw buffers as the host's own).
  virtual GLuint geometryTarget(GLuint own) { return own; }
  virtual int geometryScale() { return 1; }
  virtual glm::vec2 projectionJitter() { return glm::vec2(0.0f); }  // this frame's sub-pixel shift (a history's jitter)
  virtual float textureLodBias() {
    return 0.0f;
  }  // added to the material samplers' mip bias  // how many times the host's size that target is
  virtual void geometryDone(const FrameView&) {}
  // After the geometry pass: an AA module that wants the geometry drawn once more (a multisampled depth
  // and normal prepass) gets `draw`, which clears the framebuffer it is given and draws into it.
  virtual void geometryAgain(const std::function<void(GLuint target)>&) {}
  // Runs the host's lighting (`pass`, rendering into the framebuffer it is given; it clears colour).
  virtual void lighting(const std::function<void(GLuint target)>& pass, GLuint own) { pass(own); }
  virtual void frameDone() {}  // after the forward pass, on the display
};

class SecondRenderer : public Engine {
 public:
  // `worldPositionTarget`: the geometry pass also writes world positions (location 2), which the host's
  // own lighting does not read: a third attachment for a layout that takes depth from it.
  SecondRenderer(const Scene& scene, int width, int height, bool worldPositionTarget = false);
  ~SecondRenderer() override;
  // Bytes a pixel's G-buffer takes (attachments and depth): what an AA module's multisampled mirror of it
  // takes a sample, known before any target exists.
  static uint64_t gbufferBytesPerSample(bool worldPositionTarget = false);

  void setSeams(SecondSeams* seams);  // nullptr: the stock path
  const SecondTargets& targets() const { return targets_; }
  // The projection: reversed-Z, zero-to-one depth, jittered by `jitterPixels`.
  glm::mat4 projection(const Camera& camera, glm::vec2 jitterPixels = glm::vec2(0)) const;

  void resize(int width, int height) override;
  void renderFrame(const Camera& camera, glm::vec2 jitterPixels = glm::vec2(0)) override;
  int width() const override { return targets_.width; }
  int height() const override { return targets_.height; }
  const Scene& scene() const override { return scene_; }
  GLuint displayFramebuffer() const override { return targets_.displayFramebuffer; }
  std::vector<uint8_t> readDisplay() const override;
  std::vector<float> readLight() const override;
  GLuint radianceTexture() const override { return targets_.display; }  // an sRGB texture reads as linear
  std::string groundTruthDefines() const override { return "#define DISPLAY_CLAMP 1\n"; }
  float exposure() const override { return 1.0f; }  // applied in the lighting
  void present(GLuint radiance) override;
  void setStockPath(bool stock) override;

 private:
  void createTargets(int width, int height);
  // Which objects a pass draws: the G-buffer's (all but the purely emissive), the purely emissive ones
  // (forward, opaque), and the glow of lit objects whose material has an emissive map (forward, added).
  enum class ObjectPass { Geometry, Emissive, Glow };
  void drawObjects(const Program& program, const glm::mat4& viewProjection, ObjectPass pass, float time) const;
  void lightingPass(GLuint target, const Camera& camera, const glm::mat4& projection);
  void forwardPass(const glm::mat4& viewProjection, float time);

  const Scene& scene_;
  SecondSeams stockSeams_;
  SecondSeams* seams_ = &stockSeams_;
  SecondSeams* suspendedSeams_ = nullptr;
  SecondTargets targets_;
  bool worldPositionTarget_ = false;
  Texture normal_, albedoSpecular_, depth_, display_, worldPosition_;
  Framebuffer gbufferFramebuffer_, displayFramebuffer_;
  Program geometryProgram_, sunProgram_, pointProgram_, forwardProgram_, presentProgram_;
  std::vector<GpuMesh> meshes_;
  GpuMesh sphere_;
  VertexArray emptyVertexArray_;
};

}  // namespace host
