// `resolve`: MSAA G-buffer → host G-buffer through a depth-aware weighting (shaders/resolve/).
#include <cmath>

#include "methods.h"

namespace retroaa {

Result<std::unique_ptr<ResolvePass>> ResolvePass::create(PluginContext& context, const MsaaGBuffer& source) {
  auto pass = std::make_unique<ResolvePass>();
  const GBufferLayout& layout = context.layout;
  Result<ShaderProgram> program =
      context.shaders->program("common/fullscreen.vert", "resolve/resolve.frag", source.shaderDefines(layout),
                               {RETROAA_GBUFFER_PASS_UNIFORMS, "uWeighting", "uFsoFootprintTan", "uCloseness"});
  if (!program) return program.error();
  pass->program_ = std::move(program.value());

  // The host's attachments and its depth (not its stencil: those bits belong to the host).
  pass->hostTarget_ = makeFramebuffer(context, "resolve.host_target");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < layout.attachments.size(); ++i) {
    glNamedFramebufferTexture(pass->hostTarget_.get(), GLenum(GL_COLOR_ATTACHMENT0 + i), layout.attachments[i].texture,
                              0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(pass->hostTarget_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
  glNamedFramebufferTexture(pass->hostTarget_.get(), GL_DEPTH_ATTACHMENT, layout.depthStencilTexture, 0);
  if (Status status = checkFramebuffer(pass->hostTarget_.get(), "resolve.host_target"); !status) return status.error();
  return pass;
}

namespace {
void drawResolve(PluginContext& context, const ShaderProgram& program, const MsaaGBuffer& source,
                 const FrameInfo& frame) {
  source.beginPass(program, context, frame);
  program.set("uWeighting", int(context.config.resolveWeighting));
  // FreeSpace Open's footprint: tan(fov / height) with the vertical fov it passes (msaa-f.sdr).
  program.set("uFsoFootprintTan", std::tan(frame.verticalFovRadians / float(context.layout.height)));
  program.set("uCloseness", context.config.closeness);
  context.drawFullscreen();
}
}  // namespace

Status ResolvePass::run(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame) {
  ScopedPass timed(context, "resolve");
  context.beginFullscreenPass(hostTarget_.get());
  glEnable(GL_DEPTH_TEST);  // depth writes need the test enabled; ALWAYS passes every pixel
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  drawResolve(context, program_, source, frame);
  return Status::ok();
}

Status ResolvePass::restore(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame) {
  ScopedPass timed(context, "resolve.restore");
  context.beginFullscreenPass(hostTarget_.get());  // depth test off: the depth is left as it is
  drawResolve(context, program_, source, frame);
  return Status::ok();
}

}  // namespace retroaa
