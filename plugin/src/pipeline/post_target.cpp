// The post passes' render target: they read the host's display texture and write a copy of it.
#include "pipeline.h"

#include "../shared_constants.h"

namespace retroaa {

Result<std::unique_ptr<PostTarget>> PostTarget::create(PluginContext& context) {
  auto target = std::make_unique<PostTarget>();
  const GBufferLayout& layout = context.layout;
  if (!layout.displayFramebuffer)
    return Error{ErrorCode::InvalidLayout,
                 std::string("method '") + toString(context.config.method) +
                     "' (or a filter stacked on it) filters the host's display after tonemapping: the layout names "
                     "no displayFramebuffer and displayTexture"};
  GLint displayFormat = GL_RGBA8;
  glGetTextureLevelParameteriv(layout.displayTexture, 0, GL_TEXTURE_INTERNAL_FORMAT, &displayFormat);
  const bool srgb = displayFormat == GL_SRGB8_ALPHA8;
  // The output has the display's own format (raw copies need matching sizes); an sRGB display's
  // stand-in is its non-sRGB twin.
  const GLenum workFormat = srgb ? GL_RGBA8 : GLenum(displayFormat);
  target->output_ = makeTexture(context, workFormat, layout.width, layout.height, 0, "post.output", target->bytes_);
  if (srgb)
    target->encodedCopy_ =
        makeTexture(context, GL_RGBA8, layout.width, layout.height, 0, "post.encoded_display", target->bytes_);
  target->framebuffer_ = makeFramebuffer(context, "post.output");
  glNamedFramebufferTexture(target->framebuffer_.get(), GL_COLOR_ATTACHMENT0, target->output_.get(), 0);
  if (Status status = checkFramebuffer(target->framebuffer_.get(), "post.output"); !status) return status.error();
  // A linear display is averaged as stored: no decoding view (an sRGB format is encoded whatever the layout says).
  target->linearValues_ = !srgb && layout.displayEncoding == DisplayEncoding::Linear;
  if (workFormat == GL_RGBA8 && !target->linearValues_) {
    GLuint view = 0;
    glGenTextures(1, &view);  // a view needs a name that was never bound
    glTextureView(view, GL_TEXTURE_2D, target->output_.get(), GL_SRGB8_ALPHA8, 0, 1, 0, 1);
    glObjectLabel(GL_TEXTURE, view, -1, "retroaa.post.output_as_linear");
    target->linearView_ = GlTexture(context.objects, view);
  }
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  target->linear_ = GlSampler(context.objects, sampler);
  return target;
}

std::string PostTarget::encodingDefine() const { return defineLine("DISPLAY_HOLDS_LINEAR", linearValues_); }

void PostTarget::bindAsOutput(const PluginContext& context) const { context.beginFullscreenPass(framebuffer_.get()); }

void PostTarget::begin(const GBufferLayout& layout) const {
  if (encodedCopy_) copyLayoutTexture(layout, layout.displayTexture, encodedCopy_.get());
}

void PostTarget::end(const GBufferLayout& layout) const {
  if (encodedCopy_) copyLayoutTexture(layout, encodedCopy_.get(), layout.displayTexture);
}

void PostTarget::bindBilinear(const ShaderProgram& program, const char* sampler, GLuint texture) const {
  const int unit = program.unit(sampler);
  if (unit < 0) return;
  glBindTextureUnit(GLuint(unit), texture);
  glBindSampler(GLuint(unit), linear_.get());
}

void PostTarget::copyBack(const GBufferLayout& layout) const {
  copyLayoutTexture(layout, output_.get(), input(layout));
}

void PostTarget::copyInputAside(const GBufferLayout& layout) const {
  copyLayoutTexture(layout, input(layout), output_.get());
}

}  // namespace retroaa
