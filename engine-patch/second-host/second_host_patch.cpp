#include "second_host_patch.h"

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
  auto log = [](retroaa::LogLevel, const std::string& m) { std::fprintf(stderr, "retroaa: %s\n", m.c_str()); };
  auto plugin = retroaa::Plugin::create({config, describeSecondHost(targets), log});
  if (!plugin) return plugin.error();
  auto hooks = std::make_unique<SecondHostHooks>();
  hooks->plugin_ = std::move(plugin.value());
  return hooks;
}

}  // namespace patch
