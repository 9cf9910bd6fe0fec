// The host's forward passes after shade(): multisampled over the MSAA G-buffer's depth (ForwardTarget), and
// what they drew (ForwardMask).
#include "../shared_constants.h"
#include "pipeline.h"

namespace retroaa {

Result<std::unique_ptr<ForwardTarget>> ForwardTarget::create(PluginContext& context, const MsaaGBuffer& source) {
  const GBufferLayout& layout = context.layout;
  auto target = std::make_unique<ForwardTarget>();
  target->colour_ =
      makeTexture(context, GL_RGBA16F, layout.width, layout.height, source.samples(), "forward.colour", target->bytes_);
  GLint samples = 1;
  glGetTextureLevelParameteriv(target->colour_.get(), 0, GL_TEXTURE_SAMPLES, &samples);
  target->framebuffer_ = makeFramebuffer(context, "forward");
  glNamedFramebufferTexture(target->framebuffer_.get(), GL_COLOR_ATTACHMENT0, target->colour_.get(), 0);
  const GLenum depthFormat = sizedDepthFormat(source.depthStencil());
  glNamedFramebufferTexture(target->framebuffer_.get(),
                            hasStencil(depthFormat) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                            source.depthStencil(), 0);
  if (Status status = checkFramebuffer(target->framebuffer_.get(), "forward"); !status) return status.error();
  target->sceneColour_ = makeFramebuffer(context, "forward.scene_colour");
  glNamedFramebufferTexture(target->sceneColour_.get(), GL_COLOR_ATTACHMENT0, sceneColourTexture(layout), 0);
  if (Status status = checkFramebuffer(target->sceneColour_.get(), "forward.scene_colour"); !status)
    return status.error();
  auto fill = context.shaders->program("common/fullscreen.vert", "forward/fill.frag", "", {"uSceneColour"});
  if (!fill) return fill.error();
  target->fill_ = std::move(fill.value());
  target->shadedColour_ = makeLightTargetCopy(context, "forward.shaded_colour", target->bytes_);
  auto carry = context.shaders->program("common/fullscreen.vert", "forward/carry_change.frag", "",
                                        {"uSceneColour", "uShadedColour"});
  if (!carry) return carry.error();
  target->carry_ = std::move(carry.value());
  auto keep = context.shaders->program("common/fullscreen.vert", "forward/keep_sample.frag", "",
                                       {"uSliceColour", "uSliceCounts", "uMinCount", "uSample"});
  if (!keep) return keep.error();
  target->keep_ = std::move(keep.value());
  auto resolve = context.shaders->program("common/fullscreen.vert", "forward/resolve.frag",
                                          defineLine("SAMPLES", samples), {"uForward"});
  if (!resolve) return resolve.error();
  target->resolve_ = std::move(resolve.value());
  return target;
}

void ForwardTarget::beginFrame(const PluginContext& context) const {
  shadedColourKept_ = false;
  context.beginFullscreenPass(framebuffer_.get());  // a clear obeys the colour mask and scissor
  const float nothingKept[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(framebuffer_.get(), GL_COLOR, 0, nothingKept);
}

void ForwardTarget::keepSample(PluginContext& context, GLuint sliceColour, GLuint counts, int minCount, int sample,
                               const TileDraw& tiles) const {
  ScopedPass timed(context, "forward.keep");
  context.beginFullscreenPass(framebuffer_.get());
  glEnable(GL_MULTISAMPLE);  // gl_SampleMask counts only with it (Irrlicht, for one, turns it off)
  glDisable(GL_SAMPLE_SHADING);
  glDisable(GL_FRAMEBUFFER_SRGB);
  keep_.use();
  keep_.bindTexture("uSliceColour", sliceColour);
  keep_.bindTexture("uSliceCounts", counts);
  keep_.set("uMinCount", minCount);
  keep_.set("uSample", sample);
  context.drawTiles(tiles);
}

void ForwardTarget::keepShadedColour(const GBufferLayout& layout) const {
  copyLightTarget(layout, shadedColour_.get());
  shadedColourKept_ = true;
}

void ForwardTarget::fill(PluginContext& context) const {
  ScopedPass timed(context, "forward.fill");
  context.beginFullscreenPass(framebuffer_.get());
  glEnable(GL_MULTISAMPLE);        // blended against each sample's own alpha
  glDisable(GL_FRAMEBUFFER_SRGB);  // the values as the scene colour's texture unit returns them (linear)
  glEnable(GL_BLEND);
  if (shadedColourKept_) {
    glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE);  // the change into kept samples (alpha 1)
    carry_.use();
    carry_.bindTexture("uSceneColour", sceneColourTexture(context.layout));
    carry_.bindTexture("uShadedColour", shadedColour_.get());
    context.drawFullscreen();
  }
  // colour where nothing was kept (alpha 0); alpha the scene colour's
  glBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA, GL_ONE, GL_ZERO);
  fill_.use();
  fill_.bindTexture("uSceneColour", sceneColourTexture(context.layout));
  context.drawFullscreen();
}

void ForwardTarget::resolve(PluginContext& context) const {
  ScopedPass timed(context, "forward.resolve");
  context.beginFullscreenPass(sceneColour_.get());
  glEnable(GL_FRAMEBUFFER_SRGB);  // an sRGB scene colour stores the linear mean encoded
  resolve_.use();
  resolve_.bindTexture("uForward", colour_.get());
  context.drawFullscreen();
}

Result<std::unique_ptr<ForwardMask>> ForwardMask::create(PluginContext& context) {
  const GBufferLayout& layout = context.layout;
  auto mask = std::make_unique<ForwardMask>();
  mask->before_ = makeLightTargetCopy(context, "forward_mask.before", mask->bytes_);
  mask->drawn_ = makeTexture(context, GL_R8, layout.width, layout.height, 0, "forward_mask.drawn", mask->bytes_);
  mask->framebuffer_ = makeFramebuffer(context, "forward_mask");
  glNamedFramebufferTexture(mask->framebuffer_.get(), GL_COLOR_ATTACHMENT0, mask->drawn_.get(), 0);
  if (Status status = checkFramebuffer(mask->framebuffer_.get(), "forward_mask"); !status) return status.error();
  auto mark = context.shaders->program("common/fullscreen.vert", "forward/mark_drawn.frag", "", {"uBefore", "uAfter"});
  if (!mark) return mark.error();
  mask->mark_ = std::move(mark.value());
  return mask;
}

void ForwardMask::clear() const {
  const float nothing[4] = {0, 0, 0, 0};
  glClearTexImage(drawn_.get(), 0, GL_RED, GL_FLOAT, nothing);
}

void ForwardMask::keepSceneColour(const GBufferLayout& layout) const { copyLightTarget(layout, before_.get()); }

void ForwardMask::markChanges(PluginContext& context) const {
  ScopedPass timed(context, "forward.mask");
  context.beginFullscreenPass(framebuffer_.get());
  mark_.use();
  mark_.bindTexture("uBefore", before_.get());
  mark_.bindTexture("uAfter", sceneColourTexture(context.layout));
  context.drawFullscreen();
}

}  // namespace retroaa
