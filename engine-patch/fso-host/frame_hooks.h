// The seams of the host's frame where an AA module may step in. The stock implementation is the
// host's own single-sample path; retroaa_hooks.cpp beside it provides the one that calls retroaa.
// Each hook names the FreeSpace Open function it corresponds to (docs/integration.md).
#pragma once

#include "engine.h"

#include <epoxy/gl.h>

#include <glm/glm.hpp>

#include <functional>

namespace host {

// The host's render targets, handed out whenever they are (re)created.
struct HostTargets {
  int width = 0, height = 0;
  GLuint gbufferFramebuffer = 0;                                           // attachments 0..4 + depth-stencil
  GLuint color = 0, position = 0, normal = 0, specular = 0, emissive = 0;  // textures
  GLuint depthStencil = 0;                                                 // DEPTH24_STENCIL8 texture
  GLuint velocity = 0;  // RG16F attachment 5: screen motion in pixels (this − previous); 0: not written
  GLuint lightFramebuffer = 0, lightTexture = 0;      // RGBA16F light accumulation ("composite")
  GLuint displayFramebuffer = 0, displayTexture = 0;  // RGBA8 tonemapped output
  bool logarithmicDepth = true;        // depth buffer holds log2(d/near)/log2(far/near), else perspective depth
  bool fsoCompressedPosition = false;  // position z is FSO's compressed view z (fso_z), else depth_codec
  float globalFarZ = 2.0e6f;           // metres: FSO's GLOBAL_FAR_Z for fso_z (the camera's far plane)
};

// Draws the frame's models again into `target` with the model shaders; the target's draw buffers
// decide which outputs are kept (none: depth only).
using ModelPrepass = std::function<void(GLuint target)>;

// The host's lighting pass: renders every light of the frame, reading the host's single-sample
// G-buffer, into `target` (a framebuffer with one RGBA16F colour attachment).
using LightingPass = std::function<void(GLuint target)>;

class FrameHooks {
 public:
  virtual ~FrameHooks() = default;
  // opengl_setup_scene_textures(): the host (re)created its targets.
  virtual void targetsCreated(const HostTargets&) {}
  // gr_set_proj_matrix() (code/graphics/matrix.cpp, for the 3D scene): a sub-pixel shift, in pixels, of
  // this frame's projection (an AA module that accumulates a jittered history).
  virtual glm::vec2 projectionJitter() { return glm::vec2(0.0f); }
  // The material samplers' mip bias the AA module asks for (with a jittered history: sharper mips, which
  // the history averages). FSO sets no bias today: the patch adds GL_TEXTURE_LOD_BIAS where it sets its model
  // textures' sampling state.
  virtual float textureLodBias() { return 0.0f; }
  // gr_opengl_deferred_lighting_begin(): the framebuffer the background and models render into.
  virtual GLuint modelPassFramebuffer(GLuint stockGbuffer) { return stockGbuffer; }
  // ...and how many times the host's width and height that framebuffer is (the model pass's viewport).
  virtual int modelPassScale() { return 1; }
  // gr_opengl_deferred_lighting_msaa() / _end(): the model pass is done.
  virtual void modelPassEnd(const FrameView&) {}
  // After the model pass: an AA module that wants a multisampled copy of the models' depth (and
  // normals) draws them here. FreeSpace Open has no such call site: it would
  // be a second model loop at the end of gr_opengl_deferred_lighting_end() into that framebuffer.
  virtual void modelPrepass(const ModelPrepass&) {}
  // gr_opengl_deferred_lighting_finish(): run the host's lighting.
  virtual void lighting(const LightingPass& pass, GLuint stockLightFramebuffer) { pass(stockLightFramebuffer); }
  // gr_opengl_post_process_end(): after tonemapping, on the display target.
  virtual void postProcess() {}
};

}  // namespace host
