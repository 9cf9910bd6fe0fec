// The second host's patch: the only code of that host that knows retroaa (with second_host_patch.cpp).
#pragma once
#include "frame_info.h"
#include "retroaa/plugin.h"
#include "second_renderer.h"

#include <cstdio>

namespace patch {

retroaa::GBufferLayout describeSecondHost(const host::SecondTargets& targets);

class SecondHostHooks : public host::SecondSeams {
 public:
  static retroaa::Result<std::unique_ptr<SecondHostHooks>> create(const host::SecondTargets&, const retroaa::Config&);
  void targetsCreated(const host::SecondTargets& t) override { report(plugin_->resize(describeSecondHost(t))); }
  GLuint geometryTarget(GLuint) override { return plugin_->geometryFramebuffer(); }
  int geometryScale() override { return plugin_->geometryScale(); }
  glm::vec2 projectionJitter() override { return {plugin_->jitter().x, plugin_->jitter().y}; }
  float textureLodBias() override { return plugin_->textureLodBias(); }
  void geometryDone(const host::FrameView& v) override { report(plugin_->resolve(frameInfo(v))); }
  void geometryAgain(const std::function<void(GLuint)>& draw) override {
    if (const GLuint target = plugin_->prepassFramebuffer()) draw(target);  // a method with a prepass
  }
  void lighting(const std::function<void(GLuint)>& pass, GLuint) override { report(plugin_->shade(pass)); }
  void frameDone() override { report(plugin_->post()); }
  retroaa::Plugin& plugin() { return *plugin_; }
  const std::string& lastError() const { return lastError_; }

 private:
  void report(const retroaa::Status& s) {
    if (!s && lastError_.empty()) std::fprintf(stderr, "retroaa: %s\n", (lastError_ = s.error().message).c_str());
  }
  std::unique_ptr<retroaa::Plugin> plugin_;
  std::string lastError_;
};

}  // namespace patch
