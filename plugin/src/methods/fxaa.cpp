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
    // The contrast test marks the pixels the search and blend rewrite in place (shaders/fxaa/fxaa.frag).
    auto rewrite = MarkedRewrite::create(context, shared.post->input(layout), "fxaa", t.bytes_);
    if (!rewrite) return rewrite.error();
    t.rewrite_ = std::move(rewrite.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo&) override {
    ScopedPass timed(context, "fxaa");
    const GBufferLayout& layout = context.layout;
    shared.post->copyInputAside(layout);  // what both draws read
    rewrite_.run(context, markProgram_, filterProgram_, [&](const ShaderProgram& program) {
      program.use();
      shared.post->bindBilinear(program, "uInput", shared.post->copyOfInput());
      program.set("uTexelSize", 1.0f / layout.width, 1.0f / layout.height);
      program.set("uEdgeThreshold", context.config.fxaaEdgeThreshold);
      program.set("uEdgeThresholdMin", 0.0312f);
      program.set("uSubpixel", 0.75f);
    });
    return Status::ok();
  }

  bool keepsObjectsFor(const Config& config) const override { return config.fxaaQuality == quality_; }

  uint64_t bytes() const override { return bytes_; }

 private:
  ShaderProgram markProgram_, filterProgram_;
  MarkedRewrite rewrite_;
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
