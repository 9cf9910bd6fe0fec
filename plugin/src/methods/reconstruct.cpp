// `reconstruct` (after Chajdas, McGuire and Luebke, "Subpixel Reconstruction Antialiasing", I3D 2011):
// shading stays the host's stock single-sample path; a multisampled prepass of the host's own model
// shaders keeps only depth and the normal; after tonemapping, every sub-sample that does not belong to
// its own pixel's surface takes the colour of the neighbouring shaded pixels that match it
// (shaders/reconstruct/). Stacked on a G-buffer method (`reconstruct_filter=on`) it reads the MSAA
// G-buffer's own depth and normals instead of a prepass.
#include <initializer_list>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

class ReconstructTechnique : public SampleGeometryTechnique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<ReconstructTechnique>();
    if (Status status = technique->createGeometry(context, shared, Method::Reconstruct, true, "reconstruct"); !status)
      return status.error();
    ReconstructTechnique& t = *technique;
    const GBufferLayout& layout = context.layout;
    if (const int normal = findRole(layout, AttachmentRole::NormalGloss); normal >= 0)
      t.pixelNormal_ = layout.attachments[size_t(normal)].texture;
    t.beforeTonemap_ = context.config.reconstructBeforeTonemap;
    t.searchRadius_ = context.config.reconstructSearchRadius;
    t.linearInput_ = !t.beforeTonemap_ && shared.post->linearCopyOfInput() != 0;
    if (t.beforeTonemap_ && !sceneColourTexture(layout))
      return Error{ErrorCode::InvalidLayout,
                   "reconstruct_before_tonemap=on filters the light target: the layout names no lightTexture"};
    if (t.beforeTonemap_) {  // a copy of the light target to read neighbours from while writing it
      t.radiance_ = makeLightTargetCopy(context, "reconstruct.radiance", t.geometry_.bytes);
    }
    t.output_ = t.beforeTonemap_ ? sceneColourTexture(layout) : shared.post->input(layout);
    GLint outputFormat = GL_RGBA8;
    glGetTextureLevelParameteriv(t.output_, 0, GL_TEXTURE_INTERNAL_FORMAT, &outputFormat);
    t.outputFormat_ = GLenum(outputFormat);
    t.computeRequested_ = context.config.reconstructCompute;
    t.compute_ = t.computeRequested_ && takesImageStores(t.outputFormat_);
    if (t.computeRequested_ && !t.compute_)
      context.warn("reconstruct_compute=on: the " + std::string(t.beforeTonemap_ ? "light target" : "display") +
                   "'s format takes no image stores; using the full-screen pass");
    const std::string defines = defineLine("SAMPLES", t.geometry_.samples) + depthEncodingDefines(layout) +
                                defineLine("HAS_NORMALS", t.geometry_.normal != 0) +
                                defineLine("PACKED_SAMPLE_NORMALS", t.geometry_.packedNormals) +
                                defineLine("RADIANCE", t.beforeTonemap_) + defineLine("LINEAR_INPUT", t.linearInput_) +
                                (t.beforeTonemap_ ? std::string() : shared.post->encodingDefine()) +
                                defineLine("SEARCH_RADIUS", t.searchRadius_) +
                                t.forwardMaskDefine(layout, !t.beforeTonemap_);  // before tonemapping: before them
    if (t.compute_) {
      auto program = context.shaders->computeProgram("reconstruct/reconstruct.comp", defines, kUniforms);
      if (!program) return program.error();
      t.program_ = std::move(program.value());
      return std::unique_ptr<Technique>(std::move(technique));
    }
    for (const bool marking : {true, false}) {
      auto program = context.shaders->program("common/fullscreen.vert", "reconstruct/reconstruct.frag",
                                              defines + defineLine("RECONSTRUCT_MARK", marking), kUniforms);
      if (!program) return program.error();
      (marking ? t.markProgram_ : t.program_) = std::move(program.value());
    }
    auto rewrite = MarkedRewrite::create(context, t.output_, "reconstruct", t.geometry_.bytes);
    if (!rewrite) return rewrite.error();
    t.rewrite_ = std::move(rewrite.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status afterLighting(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    if (!beforeTonemap_) return Status::ok();
    ScopedPass timed(context, "reconstruct");
    const GBufferLayout& layout = context.layout;
    copyLightTarget(layout, radiance_.get());
    run(context, shared, frame, radiance_.get());
    return Status::ok();
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    if (beforeTonemap_) return Status::ok();
    ScopedPass timed(context, "reconstruct");
    shared.post->copyInputAside(context.layout);
    run(context, shared, frame, linearInput_ ? shared.post->linearCopyOfInput() : shared.post->copyOfInput());
    return Status::ok();
  }

  bool keepsObjectsFor(const Config& config) const override {
    return SampleGeometryTechnique::keepsObjectsFor(config) && config.reconstructBeforeTonemap == beforeTonemap_ &&
           config.reconstructSearchRadius == searchRadius_ && config.reconstructCompute == computeRequested_;
  }

 private:
  static constexpr std::initializer_list<const char*> kUniforms = {"uSamplePositions", RETROAA_DEPTH_BUFFER_UNIFORMS,
                                                                   "uFootprintTan",    "uTolerance",
                                                                   "uInput",           "uPixelDepth",
                                                                   "uPixelNormal",     "uSampleDepth",
                                                                   "uSampleNormal",    "uForwardDrawn"};
  static constexpr int kTileSize = 8;  // reconstruct.comp's work group: 8 × 8 pixels

  // The pass itself: `input`, a copy of output_, rewritten into output_.
  void run(PluginContext& context, const SharedTargets& shared, const FrameInfo& frame, GLuint input) {
    const GBufferLayout& layout = context.layout;
    const float footprintTan = context.footprintTan(frame);
    const auto bind = [&](const ShaderProgram& program) {
      program.use();
      program.bindTexture("uInput", input);
      bindForwardMask(program, shared);
      program.bindTexture("uPixelDepth", layout.depthStencilTexture);
      program.bindTexture("uPixelNormal", pixelNormal_);
      program.bindTexture("uSampleDepth", geometry_.depth);
      program.bindTexture("uSampleNormal", geometry_.normal);
      program.setVec2Array("uSamplePositions", geometry_.samples, geometry_.samplePositions.data());
      program.setDepthPlanes(context);
      program.set("uFootprintTan", footprintTan);
      program.set("uTolerance", context.config.reconstructTolerance);
    };
    if (compute_) {
      bind(program_);
      context.dispatchOverScreen({{output_, outputFormat_}}, kTileSize);
    } else {
      rewrite_.run(context, markProgram_, program_, bind);
    }
  }

  ShaderProgram program_;      // the rebuild (the fragment pass: of the marked pixels)
  ShaderProgram markProgram_;  // the fragment pass: marks the pixels to rebuild
  MarkedRewrite rewrite_;
  GLuint output_ = 0;  // what the pass rewrites: the display (post's input()) or the light target
  GLenum outputFormat_ = GL_RGBA8;
  bool compute_ = false;           // reconstruct.comp: asked for, and outputFormat_ takes image stores
  bool computeRequested_ = false;  // reconstruct_compute as created
  GlTexture radiance_;             // before tonemapping: the light target as lit
  GLuint pixelNormal_ = 0;         // the host's single-sample normal attachment (0: the layout has none)
  bool beforeTonemap_ = false;
  bool linearInput_ = false;  // the display is read through its sRGB view, decoded by the texture unit
  int searchRadius_ = 1;      // compiled into the program
};

}  // namespace

Result<std::unique_ptr<Technique>> createReconstructTechnique(PluginContext& context, SharedTargets& shared) {
  return ReconstructTechnique::create(context, shared);
}

// The config keys of `reconstruct` and `+reconstruct` (its registry row lists them: registry.cpp).
std::vector<Key> reconstructKeys() {
  return {
      onOff("reconstruct_filter", &Config::reconstructFilter,
            "sub-pixel reconstruction on top of resolve (reuses its MSAA depth and normals; no prepass)"),
      number("reconstruct_tolerance", &Config::reconstructTolerance, 0, 100,
             "c of the depth test that ties a sub-sample to a shaded pixel"),
      integer("reconstruct_search_radius", &Config::reconstructSearchRadius, 1, 8,
              "how many rings of pixels a sub-sample searches for its surface when no neighbour holds "
              "it (sub-pixel wires: a pixel centre on the same wire lies a few pixels along it)"),
      onOff("reconstruct_before_tonemap", &Config::reconstructBeforeTonemap,
            "reconstruct on the HDR light target before tonemapping (+8 B/px) instead of on the display"),
      onOff("reconstruct_compute", &Config::reconstructCompute,
            "reconstruct as a compute pass that packs each 8x8 tile's searching pixels onto adjacent invocations "
            "instead of a full-screen pass (the same image; where the target's format takes no image stores, the "
            "full-screen pass with a warning)"),
  };
}

}  // namespace retroaa
