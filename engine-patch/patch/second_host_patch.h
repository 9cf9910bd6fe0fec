// The second host's patch: the only code of that host that knows retroaa (second_host_patch.cpp).
#pragma once

#include "retroaa/plugin.h"
#include "second_renderer.h"

#include <memory>
#include <string>

namespace patch {

retroaa::GBufferLayout describeSecondHost(const host::SecondTargets& targets);

class SecondHostHooks : public host::SecondSeams {
 public:
  static retroaa::Result<std::unique_ptr<SecondHostHooks>> create(const host::SecondTargets& targets,
                                                                  const retroaa::Config& config);
  void targetsCreated(const host::SecondTargets& targets) override;
  GLuint geometryTarget(GLuint own) override;
  void geometryDone(const host::FrameView& view) override;
  void geometryAgain(const std::function<void(GLuint)>& draw) override;
  void lighting(const std::function<void(GLuint)>& pass, GLuint own) override;
  void frameDone() override;
  retroaa::Plugin& plugin() { return *plugin_; }
  const std::string& lastError() const { return lastError_; }

 private:
  void report(const retroaa::Status& status);
  std::unique_ptr<retroaa::Plugin> plugin_;
  std::string lastError_;
};

}  // namespace patch
