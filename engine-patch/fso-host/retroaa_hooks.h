// The engine side of the integration: the only host code that knows retroaa. It implements the
// host's FrameHooks at FreeSpace Open's call sites (docs/integration.md) by calling the plugin.
#pragma once

#include "frame_hooks.h"
#include "frame_info.h"
#include "retroaa/plugin.h"

#include <memory>
#include <string>
#include <vector>

namespace patch {

// The host's G-buffer described to the plugin by role (FSO's layout and depth encoding).
retroaa::GBufferLayout describeHostGBuffer(const host::HostTargets& targets);

class RetroaaHooks : public host::FrameHooks {
 public:
  // Creates the plugin for the host's current targets. Errors come back as the plugin's Error.
  // `disabledFeatures` and `maxSamplesLimit` mask context capabilities (retroaa::Description).
  static retroaa::Result<std::unique_ptr<RetroaaHooks>> create(const host::HostTargets& targets,
                                                               const retroaa::Config& config,
                                                               uint32_t disabledFeatures = 0, int maxSamplesLimit = 0);

  void targetsCreated(const host::HostTargets& targets) override;
  GLuint modelPassFramebuffer(GLuint stockGbuffer) override;
  int modelPassScale() override { return plugin_->geometryScale(); }
  glm::vec2 projectionJitter() override { return {plugin_->jitter().x, plugin_->jitter().y}; }
  float textureLodBias() override { return plugin_->textureLodBias(); }
  void modelPassEnd(const host::FrameView& view) override;
  void modelPrepass(const host::ModelPrepass& pass) override;
  void lighting(const host::LightingPass& pass, GLuint stockLightFramebuffer) override;
  void postProcess() override;

  retroaa::Plugin& plugin() { return *plugin_; }
  // The first error any call site met (a frame keeps rendering the stock way after one).
  const std::string& lastError() const { return lastError_; }

 private:
  void report(const retroaa::Status& status);
  std::unique_ptr<retroaa::Plugin> plugin_;
  std::string lastError_;
};

}  // namespace patch
