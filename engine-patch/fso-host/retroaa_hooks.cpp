#include "retroaa_hooks.h"

#include "depth_codec.h"

#include <unistd.h>

#include <cstdio>

namespace patch {

retroaa::GBufferLayout describeHostGBuffer(const host::HostTargets& targets) {
  using retroaa::AttachmentRole;
  retroaa::GBufferLayout layout;
  layout.width = targets.width;
  layout.height = targets.height;
  layout.attachments = {{AttachmentRole::Albedo, GL_RGBA16F, targets.color},
                        {AttachmentRole::ViewPosition, GL_RGBA16F, targets.position},
                        {AttachmentRole::NormalGloss, GL_RGBA16F, targets.normal},
                        {AttachmentRole::Specular, GL_RGBA8, targets.specular},
                        {AttachmentRole::Emissive, GL_RGBA16F, targets.emissive}};
  if (targets.velocity) {  // written where objects move on their own: a history follows it
    layout.attachments.push_back({AttachmentRole::Other, GL_RG16F, targets.velocity});
    layout.velocityAttachment = int(layout.attachments.size()) - 1;
  }
  layout.depthChannel = 2;
  if (targets.fsoCompressedPosition) {  // FreeSpace Open's own z-compress.sdr
    layout.depthEncoding.kind = retroaa::DepthEncoding::Kind::FsoCompressedViewZ;
    layout.depthEncoding.farDistance = targets.globalFarZ;
  } else {
    layout.depthEncoding.kind = retroaa::DepthEncoding::Kind::LogAboveKnee;
    layout.depthEncoding.knee = host::depth_codec::kKnee;
    layout.depthEncoding.backgroundAbove = host::depth_codec::kBackgroundThreshold;
  }
  layout.normalsInViewSpace = true;  // the model shader writes view-space normals
  // The host's Blinn-Phong exponent is exp2(gloss · 10 + 1) (lighting_common.glsl).
  layout.glossEncoding = {true, 10.0f, 1.0f};
  layout.depthBufferEncoding =
      targets.logarithmicDepth ? retroaa::DepthBufferEncoding::Logarithmic : retroaa::DepthBufferEncoding::Perspective;
  layout.gbufferFramebuffer = targets.gbufferFramebuffer;
  layout.depthStencilTexture = targets.depthStencil;
  layout.lightFramebuffer = targets.lightFramebuffer;
  layout.lightTexture = targets.lightTexture;
  layout.displayFramebuffer = targets.displayFramebuffer;
  layout.displayTexture = targets.displayTexture;
  return layout;
}

retroaa::Result<std::unique_ptr<RetroaaHooks>> RetroaaHooks::create(const host::HostTargets& targets,
                                                                    const retroaa::Config& config,
                                                                    uint32_t disabledFeatures, int maxSamplesLimit) {
  retroaa::Description description;
  description.config = config;
  description.disabledFeatures = disabledFeatures;
  description.maxSamplesLimit = maxSamplesLimit;
  description.layout = describeHostGBuffer(targets);
  description.log = [](retroaa::LogLevel, const std::string& message) {
    // On a terminal, clear a progress bar drawn in place first so the warning gets a line of its own.
    std::fprintf(stderr, "%sretroaa: warning: %s\n", isatty(2) ? "\r\033[K" : "", message.c_str());
  };
  auto plugin = retroaa::Plugin::create(description);
  if (!plugin) return plugin.error();
  auto hooks = std::unique_ptr<RetroaaHooks>(new RetroaaHooks());
  hooks->plugin_ = std::move(plugin.value());
  return hooks;
}

void RetroaaHooks::report(const retroaa::Status& status) {
  if (status || !lastError_.empty()) return;
  lastError_ = status.error().message;
  std::fprintf(stderr, "retroaa: error: %s\n", lastError_.c_str());
}

// opengl_setup_scene_textures()
void RetroaaHooks::targetsCreated(const host::HostTargets& targets) {
  report(plugin_->resize(describeHostGBuffer(targets)));
}

// gr_opengl_deferred_lighting_begin(): bind the plugin's (MSAA) G-buffer instead of the host's.
GLuint RetroaaHooks::modelPassFramebuffer(GLuint) { return plugin_->geometryFramebuffer(); }

// gr_opengl_deferred_lighting_msaa(): the depth-aware resolve replaces FSO's.
void RetroaaHooks::modelPassEnd(const host::FrameView& view) { report(plugin_->resolve(frameInfo(view))); }

// (no FSO call site yet: a second model loop into the plugin's prepass; docs/integration.md)
void RetroaaHooks::modelPrepass(const host::ModelPrepass& pass) {
  if (const GLuint target = plugin_->prepassFramebuffer()) pass(target);
}

// gr_opengl_deferred_lighting_finish(): the host's lighting runs through the plugin.
void RetroaaHooks::lighting(const host::LightingPass& pass, GLuint) {
  report(plugin_->shade([&pass](retroaa::GLuintHandle target) { pass(target); }));
}

// gr_opengl_post_process_end(): after tonemapping.
void RetroaaHooks::postProcess() { report(plugin_->post()); }

}  // namespace patch
