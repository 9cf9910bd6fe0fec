// `coverage` (Pettineo, "Deferred MSAA"): no lighting per sample; one filter pass after tonemapping
// blends silhouette pixels by the depth sub-samples' coverage (shaders/coverage/). As the method it
// owns a depth-only MSAA prepass target; stacked on a G-buffer method (`coverage_filter=on`) it reads
// the MSAA G-buffer's own depth.
#include <cmath>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

class CoverageTechnique : public SampleGeometryTechnique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<CoverageTechnique>();
    if (Status status = technique->createGeometry(context, shared, Method::Coverage, false, "coverage"); !status)
      return status.error();
    technique->litPerSample_ = shared.slices != nullptr;
    for (const bool marking : {true, false}) {
      auto program = context.shaders->program(
          "common/fullscreen.vert", "coverage/coverage_filter.frag",
          defineLine("SAMPLES", technique->geometry_.samples) + depthEncodingDefines(context.layout) +
              shared.post->encodingDefine() + defineLine("LIT_PER_SAMPLE", technique->litPerSample_) +
              technique->forwardMaskDefine(context.layout, true) + defineLine("COVERAGE_MARK_EDGES", marking),
          {"uSamplePositions", "uTexelSize", RETROAA_DEPTH_BUFFER_UNIFORMS, "uFootprintTan", "uTolerance", "uInput",
           "uPixelDepth", "uSampleDepth", "uForwardDrawn", "uSliceCounts"});
      if (!program) return program.error();
      (marking ? technique->markProgram_ : technique->blendProgram_) = std::move(program.value());
    }
    // The depth test marks the pixels the tap blends in place (shaders/coverage/coverage_filter.frag).
    auto rewrite =
        MarkedRewrite::create(context, shared.post->input(context.layout), "coverage", technique->geometry_.bytes);
    if (!rewrite) return rewrite.error();
    technique->rewrite_ = std::move(rewrite.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    ScopedPass timed(context, "coverage_filter");
    const GBufferLayout& layout = context.layout;
    shared.post->copyInputAside(layout);  // what both draws read
    rewrite_.run(context, markProgram_, blendProgram_, [&](const ShaderProgram& program) {
      program.use();
      shared.post->bindBilinear(program, "uInput", shared.post->copyOfInput());
      program.bindTexture("uPixelDepth", layout.depthStencilTexture);
      program.bindTexture("uSampleDepth", geometry_.depth);
      bindForwardMask(program, shared);
      if (litPerSample_) program.bindTexture("uSliceCounts", shared.slices->counts());
      program.setVec2Array("uSamplePositions", geometry_.samples, geometry_.samplePositions.data());
      program.set("uTexelSize", 1.0f / layout.width, 1.0f / layout.height);
      program.setDepthPlanes(context);
      program.set("uFootprintTan", context.footprintTan(frame));
      program.set("uTolerance", context.config.coverageTolerance);
    });
    return Status::ok();
  }

  bool keepsObjectsFor(const Config& config) const override {
    const TechniqueRow* base = findTechnique(config.method);
    return SampleGeometryTechnique::keepsObjectsFor(config) &&
           litPerSample_ == (base && (base->storage & kStorageSlices));
  }

 private:
  ShaderProgram markProgram_, blendProgram_;
  MarkedRewrite rewrite_;
  bool litPerSample_ = false;  // over a slice method: the pixels it lit per sample pass through
};

}  // namespace

Result<std::unique_ptr<Technique>> createCoverageTechnique(PluginContext& context, SharedTargets& shared) {
  return CoverageTechnique::create(context, shared);
}

// The config keys of `coverage` and `+coverage` (its registry row lists them: registry.cpp).
std::vector<Key> coverageKeys() {
  return {
      onOff("coverage_filter", &Config::coverageFilter,
            "the coverage filter on top of resolve (reuses its MSAA depth; no prepass)"),
      number("coverage_tolerance", &Config::coverageTolerance, 0, 100,
             "c of the depth test; smaller finds more edges, false ones on grazing surfaces"),
  };
}

}  // namespace retroaa
