// `resolve`: MSAA G-buffer → host G-buffer through a depth-aware weighting (shaders/resolve/).
#include <cmath>
#include <string>

#include "methods.h"

namespace retroaa {

namespace {

// The layout-specific part of the resolve shader: sample count, roles and one output per attachment.
std::string resolveDefines(const GBufferLayout& layout, const MsaaGBuffer& source, int positionIndex, int normalIndex) {
  const size_t count = layout.attachments.size();
  std::string d;
  d += "#define SAMPLES " + std::to_string(source.samples()) + "\n";
  d += "#define MULTISAMPLED " + std::string(source.multisampled() ? "1" : "0") + "\n";
  d += "#define ATTACHMENT_COUNT " + std::to_string(count) + "\n";
  d += "#define POSITION_ATTACHMENT " + std::to_string(positionIndex) + "\n";
  d += "#define NORMAL_ATTACHMENT " + std::to_string(normalIndex) + "\n";
  d += "#define DEPTH_CHANNEL " + std::to_string(layout.depthChannel) + "\n";
  d += "#define DEPTH_ENCODING " +
       std::string(layout.depthEncoding.kind == DepthEncoding::Kind::LogAboveKnee ? "1" : "0") + "\n";
  std::string store = "#define STORE_OUTPUTS(v)";
  for (size_t i = 0; i < count; ++i) {
    d += "layout(location = " + std::to_string(i) + ") out vec4 out" + std::to_string(i) + ";\n";
    store += " out" + std::to_string(i) + " = v[" + std::to_string(i) + "];";
  }
  return d + store + "\n";
}

int findRole(const GBufferLayout& layout, AttachmentRole role) {
  for (size_t i = 0; i < layout.attachments.size(); ++i)
    if (layout.attachments[i].role == role) return static_cast<int>(i);
  return -1;
}

}  // namespace

Result<std::unique_ptr<ResolvePass>> ResolvePass::create(PluginContext& context, const MsaaGBuffer& source) {
  auto pass = std::make_unique<ResolvePass>();
  const GBufferLayout& layout = context.layout;
  const int position = findRole(layout, AttachmentRole::ViewPosition);
  const int normal = findRole(layout, AttachmentRole::NormalGloss);
  Result<GlProgram> program = context.shaders->program(
      "common/fullscreen.vert", "resolve/resolve.frag", resolveDefines(layout, source, position, normal));
  if (!program) return program.error();
  pass->program_ = std::move(program.value());

  // The host's attachments and its depth (not its stencil: those bits belong to the host).
  pass->hostTarget_ = makeFramebuffer(context, "resolve.host_target");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < layout.attachments.size(); ++i) {
    glNamedFramebufferTexture(pass->hostTarget_.get(), GLenum(GL_COLOR_ATTACHMENT0 + i),
                              layout.attachments[i].texture, 0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(pass->hostTarget_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
  glNamedFramebufferTexture(pass->hostTarget_.get(), GL_DEPTH_ATTACHMENT, layout.depthStencilTexture, 0);
  if (Status status = checkFramebuffer(pass->hostTarget_.get(), "resolve.host_target"); !status)
    return status.error();
  return pass;
}

Status ResolvePass::run(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame) {
  ScopedPass timed(context, "resolve");
  const GBufferLayout& layout = context.layout;
  const GLuint program = program_.get();
  glBindFramebuffer(GL_FRAMEBUFFER, hostTarget_.get());
  glViewport(0, 0, layout.width, layout.height);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);  // depth writes need the test enabled; ALWAYS passes every pixel
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glUseProgram(program);
  for (size_t i = 0; i < layout.attachments.size(); ++i) glBindTextureUnit(GLuint(i), source.attachment(i));
  glBindTextureUnit(15, source.depthStencil());
  glUniform1i(glGetUniformLocation(program, "uWeighting"), int(context.config.resolveWeighting));
  glUniform1f(glGetUniformLocation(program, "uFootprintTan"),
              std::tan(frame.horizontalFovRadians / float(layout.width)));
  glUniform1f(glGetUniformLocation(program, "uFsoFootprintTan"),
              std::tan(frame.horizontalFovRadians / float(layout.height)));
  glUniform1f(glGetUniformLocation(program, "uCloseness"), context.config.closeness);
  glUniform1f(glGetUniformLocation(program, "uDepthKnee"), layout.depthEncoding.knee);
  glUniform1f(glGetUniformLocation(program, "uBackgroundAbove"), layout.depthEncoding.backgroundAbove);
  context.drawFullscreen();
  return Status::ok();
}

}  // namespace retroaa
