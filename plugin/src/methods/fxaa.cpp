// `fxaa`: Lottes' FXAA 3.11 (quality variant) on the tonemapped display target (shaders/fxaa/); as a
// method, or stacked after any other (`fxaa=on`).
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

int searchSteps(FxaaQuality quality) {
  switch (quality) {
    case FxaaQuality::Low: return 3;
    case FxaaQuality::Medium: return 6;
    case FxaaQuality::High: return 12;
  }
  return 12;
}

class FxaaTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<FxaaTechnique>();
    FxaaTechnique& t = *technique;
    t.quality_ = context.config.fxaaQuality;
    const GBufferLayout& layout = context.layout;
    for (const bool marking : {true, false}) {
      auto program =
          context.shaders->program("common/fullscreen.vert", "fxaa/fxaa.frag",
                                   defineLine("FXAA_SEARCH_STEPS", searchSteps(t.quality_)) +
                                       defineLine("FXAA_MARK_EDGES", marking) + shared.post->encodingDefine(),
                                   {"uTexelSize", "uEdgeThreshold", "uEdgeThresholdMin", "uSubpixel", "uInput"});
      if (!program) return program.error();
      (marking ? t.markProgram_ : t.filterProgram_) = std::move(program.value());
    }
    // The pixels the contrast test keeps (shaders/fxaa/fxaa.frag): marked by the first draw, which writes
    // nothing else; the second filters them in place in the display, reading a copy of it.
    t.edgePixels_ =
        makeTexture(context, GL_STENCIL_INDEX8, layout.width, layout.height, 0, "fxaa.edge_pixels", t.bytes_);
    t.markTarget_ = makeFramebuffer(context, "fxaa.mark");
    glNamedFramebufferTexture(t.markTarget_.get(), GL_STENCIL_ATTACHMENT, t.edgePixels_.get(), 0);
    glNamedFramebufferDrawBuffer(t.markTarget_.get(), GL_NONE);
    t.filterTarget_ = makeFramebuffer(context, "fxaa.filter");
    glNamedFramebufferTexture(t.filterTarget_.get(), GL_COLOR_ATTACHMENT0, shared.post->input(layout), 0);
    glNamedFramebufferTexture(t.filterTarget_.get(), GL_STENCIL_ATTACHMENT, t.edgePixels_.get(), 0);
    for (const GLuint fbo : {t.markTarget_.get(), t.filterTarget_.get()})
      if (Status status = checkFramebuffer(fbo, "fxaa"); !status) return status.error();
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo&) override {
    ScopedPass timed(context, "fxaa");
    const GBufferLayout& layout = context.layout;
    shared.post->copyInputAside(layout);
    for (const ShaderProgram* program : {&markProgram_, &filterProgram_}) {
      const bool marking = program == &markProgram_;
      context.beginFullscreenPass(marking ? markTarget_.get() : filterTarget_.get());
      glEnable(GL_STENCIL_TEST);
      if (marking) {
        const GLint unmarked = 0;
        glStencilMask(0xFF);  // clears obey the write mask
        glClearNamedFramebufferiv(markTarget_.get(), GL_STENCIL, 0, &unmarked);
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      } else {
        glStencilFunc(GL_EQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      }
      program->use();
      shared.post->bindBilinear(*program, "uInput", shared.post->copyOfInput());
      program->set("uTexelSize", 1.0f / layout.width, 1.0f / layout.height);
      program->set("uEdgeThreshold", context.config.fxaaEdgeThreshold);
      program->set("uEdgeThresholdMin", 0.0312f);
      program->set("uSubpixel", 0.75f);
      context.drawFullscreen();
    }
    return Status::ok();
  }

  bool keepsObjectsFor(const Config& config) const override { return config.fxaaQuality == quality_; }

  uint64_t bytes() const override { return bytes_; }

 private:
  ShaderProgram markProgram_, filterProgram_;
  GlTexture edgePixels_;  // stencil: 1 where the contrast test passed
  GlFramebuffer markTarget_, filterTarget_;
  FxaaQuality quality_ = FxaaQuality::High;
  uint64_t bytes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Technique>> createFxaaTechnique(PluginContext& context, SharedTargets& shared) {
  return FxaaTechnique::create(context, shared);
}

// The config keys of `fxaa` and `+fxaa` (its registry row lists them: registry.cpp).
std::vector<Key> fxaaKeys() {
  return {
      onOff("fxaa", &Config::fxaa, "FXAA after tonemapping, stacked on the method"),
      named("fxaa_quality", &Config::fxaaQuality, kFxaaQualities,
            "FXAA edge search length (3, 6, 12 steps); cost grows with it"),
      number("fxaa_edge_threshold", &Config::fxaaEdgeThreshold, 0.063f, 0.333f,
             "FXAA local contrast needed to filter; lower softens more"),
  };
}

}  // namespace retroaa
