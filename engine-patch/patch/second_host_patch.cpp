#include "second_host_patch.h"

#include <cstdio>

namespace patch {

retroaa::GBufferLayout describeSecondHost(const host::SecondTargets& t) {
  retroaa::GBufferLayout layout;
  layout.width = t.width;
  layout.height = t.height;
  layout.attachments = {{retroaa::AttachmentRole::NormalGloss, GL_RG16F, t.normal},
                        {retroaa::AttachmentRole::Albedo, GL_RGBA8, t.albedoSpecular}};
  layout.depthSource = retroaa::DepthSource::DepthBuffer;  // no position target: rebuilt from depth
  layout.depthBufferEncoding = retroaa::DepthBufferEncoding::ReversedPerspective;
  layout.normalEncoding = retroaa::NormalEncoding::Octahedral;
  layout.gbufferFramebuffer = t.gbufferFramebuffer;
  layout.depthStencilTexture = t.depth;
  layout.lightFramebuffer = layout.displayFramebuffer = t.displayFramebuffer;  // lit straight into it
  layout.lightTexture = layout.displayTexture = t.display;
  return layout;
}

retroaa::Result<std::unique_ptr<SecondHostHooks>> SecondHostHooks::create(const host::SecondTargets& targets,
                                                                          const retroaa::Config& config) {
  retroaa::Description description;
  description.config = config;
  description.layout = describeSecondHost(targets);
  description.log = [](retroaa::LogLevel, const std::string& m) { std::fprintf(stderr, "retroaa: %s\n", m.c_str()); };
  auto plugin = retroaa::Plugin::create(description);
  if (!plugin) return plugin.error();
  auto hooks = std::make_unique<SecondHostHooks>();
  hooks->plugin_ = std::move(plugin.value());
  return hooks;
}

void SecondHostHooks::report(const retroaa::Status& status) {
  if (!status && lastError_.empty()) std::fprintf(stderr, "retroaa: %s\n", (lastError_ = status.error().message).c_str());
}
void SecondHostHooks::targetsCreated(const host::SecondTargets& t) { report(plugin_->resize(describeSecondHost(t))); }
GLuint SecondHostHooks::geometryTarget(GLuint) { return plugin_->geometryFramebuffer(); }
void SecondHostHooks::geometryDone(const host::FrameView& view) {
  report(plugin_->resolve({view.verticalFovRadians, view.nearPlane, view.farPlane}));
}
void SecondHostHooks::geometryAgain(const std::function<void(GLuint)>& draw) {
  if (const GLuint target = plugin_->prepassFramebuffer()) draw(target);  // coverage, reconstruct
}
void SecondHostHooks::lighting(const std::function<void(GLuint)>& pass, GLuint) {
  report(plugin_->shade([&pass](retroaa::GLuintHandle target) { pass(target); }));
}
void SecondHostHooks::frameDone() { report(plugin_->post()); }

}  // namespace patch
