#include "retroaa/plugin.h"

#include "budget_controller.h"
#include "context.h"
#include "gl_state.h"
#include "shared_constants.h"
#include "technique.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace retroaa {

namespace {

Status validateLayout(const GBufferLayout& layout) {
  auto invalid = [](const std::string& message) { return Error{ErrorCode::InvalidLayout, message}; };
  if (layout.width <= 0 || layout.height <= 0)
    return invalid("layout size " + std::to_string(layout.width) + "x" + std::to_string(layout.height) + " is empty");
  if (layout.attachments.empty() || layout.attachments.size() > size_t(kMaxAttachments))
    return invalid("layout has " + std::to_string(layout.attachments.size()) + " attachments (allowed: 1.." +
                   std::to_string(kMaxAttachments) + ")");
  int positions = 0, normals = 0;
  for (const Attachment& a : layout.attachments) {
    if (!a.texture || !a.internalFormat) return invalid("an attachment has no texture or no format");
    positions += a.role == AttachmentRole::ViewPosition;
    normals += a.role == AttachmentRole::NormalGloss;
  }
  const bool depthInPosition = layout.depthSource != DepthSource::DepthBuffer;
  if (depthInPosition ? positions != 1 : positions > 1)
    return invalid(
        std::string("layout needs ") + (depthInPosition ? "exactly" : "at most") +
        " one ViewPosition attachment (has " + std::to_string(positions) + ")" +
        (depthInPosition && positions == 0 ? "; a host without one sets depthSource = DepthSource::DepthBuffer" : ""));
  if (normals > 1) return invalid("layout has " + std::to_string(normals) + " NormalGloss attachments (at most one)");
  if (layout.depthChannel < 0 || layout.depthChannel > 3) return invalid("depthChannel must be 0..3");
  if (layout.velocityAttachment >= int(layout.attachments.size()))
    return invalid("velocityAttachment " + std::to_string(layout.velocityAttachment) + " names no attachment (has " +
                   std::to_string(layout.attachments.size()) + ")");
  if (layout.velocityAttachment >= 0) {
    const GLuint velocity = layout.attachments[size_t(layout.velocityAttachment)].texture;
    GLint redType = 0, greenBits = 0;
    if (glIsTexture(velocity)) {
      glGetTextureLevelParameteriv(velocity, 0, GL_TEXTURE_RED_TYPE, &redType);
      glGetTextureLevelParameteriv(velocity, 0, GL_TEXTURE_GREEN_SIZE, &greenBits);
    }
    if (redType != GL_FLOAT || greenBits == 0)
      return invalid("velocityAttachment " + std::to_string(layout.velocityAttachment) +
                     " must hold floats in at least two channels (e.g. GL_RG16F)");
  }
  const DepthEncoding& depth = layout.depthEncoding;
  if (depth.kind == DepthEncoding::Kind::LogAboveKnee && !(depth.knee > 0 && std::isfinite(depth.knee)))
    return invalid("depthEncoding.knee must be a positive number of metres");
  // FSO's last segment divides by (100 000 − GLOBAL_FAR_Z): a far distance at or below 1e5 m has none.
  if (depth.kind == DepthEncoding::Kind::FsoCompressedViewZ &&
      !(depth.farDistance > 100000.0f && std::isfinite(depth.farDistance)))
    return invalid("depthEncoding.farDistance must be above 100000 m for FsoCompressedViewZ (FSO's GLOBAL_FAR_Z)");
  if (!layout.gbufferFramebuffer || (!layout.depthStencilTexture && !layout.depthStencilRenderbuffer))
    return invalid("layout is missing the host's G-buffer (gbufferFramebuffer, depthStencilTexture)");
  if (!layout.displayFramebuffer != !layout.displayTexture)
    return invalid(
        "layout names only one of displayFramebuffer and displayTexture (both, or neither without post "
        "methods)");
  if (!layout.composedFramebuffer != !layout.composedTexture)
    return invalid(
        "layout names only one of composedFramebuffer and composedTexture (both, or neither when the "
        "shade() callback produces light)");
  if (layout.composedTexture) {
    GLint redType = 0, redBits = 0;
    if (glIsTexture(layout.composedTexture)) {
      glGetTextureLevelParameteriv(layout.composedTexture, 0, GL_TEXTURE_RED_TYPE, &redType);
      glGetTextureLevelParameteriv(layout.composedTexture, 0, GL_TEXTURE_RED_SIZE, &redBits);
    }
    if (redType != GL_FLOAT && !(redType == GL_UNSIGNED_NORMALIZED && redBits == 8))
      return invalid("composedTexture " + std::to_string(layout.composedTexture) +
                     " is not a texture of floats or 8-bit colour (e.g. GL_RGBA16F, GL_RGBA8)");
    // The slices light into the host's own light textures, which the callback's combine then reads.
    if (!layout.lightTexture || !layout.lightFramebuffer)
      return invalid(
          "a layout with a composedFramebuffer needs the lightFramebuffer and lightTexture its callback's "
          "lighting writes (the slices light into them, then compose)");
  }
  if (!layout.extraLightTextures.empty()) {
    // The slices composite into each light output directly, with blending: every one must hold floats.
    auto holdsFloats = [](GLuint texture) {
      GLint redType = 0;
      if (glIsTexture(texture)) glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_RED_TYPE, &redType);
      return redType == GL_FLOAT;
    };
    if (!holdsFloats(layout.lightTexture))
      return invalid("extraLightTextures needs a lightTexture that holds floats (lightTexture " +
                     std::to_string(layout.lightTexture) + " does not)");
    for (size_t k = 0; k < layout.extraLightTextures.size(); ++k)
      if (!holdsFloats(layout.extraLightTextures[k]))
        return invalid("extraLightTextures[" + std::to_string(k) + "] (" +
                       std::to_string(layout.extraLightTextures[k]) +
                       ") is not a texture that holds floats (e.g. GL_R11F_G11F_B10F, GL_RGBA16F)");
  }
  if (!layout.depthStencilRenderbuffer && !sizedDepthFormat(layout.depthStencilTexture)) {
    GLint format = 0;
    if (glIsTexture(layout.depthStencilTexture))
      glGetTextureLevelParameteriv(layout.depthStencilTexture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", unsigned(format));
    return invalid(
        std::string("depthStencilTexture ") + std::to_string(layout.depthStencilTexture) +
        (format ? std::string(" has internal format ") + hex + ", no depth format" : std::string(" is not a texture")) +
        " (accepted: any depth or depth-stencil texture, e.g. GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT32F, "
        "GL_DEPTH32F_STENCIL8; a renderbuffer goes in depthStencilRenderbuffer)");
  }
  return Status::ok();
}

// A host's depth renderbuffer (GBufferLayout::depthStencilRenderbuffer) mirrored in a texture of the
// same format, which every pass then uses as the host's depth texture. Depth only: the host's stencil
// stays the host's.
struct DepthMirror {
  GlTexture texture;
  GlFramebuffer hostDepth, mirrorDepth;
  int width = 0, height = 0;
  uint64_t bytes = 0;

  static Status validate(const GBufferLayout& layout) {
    if (!layout.depthStencilRenderbuffer) return Status::ok();
    if (layout.depthStencilTexture)
      return Error{ErrorCode::InvalidLayout,
                   "layout names both depthStencilTexture and depthStencilRenderbuffer (one of them)"};
    GLint depthBits = 0, samples = 0;
    if (glIsRenderbuffer(layout.depthStencilRenderbuffer)) {
      glGetNamedRenderbufferParameteriv(layout.depthStencilRenderbuffer, GL_RENDERBUFFER_DEPTH_SIZE, &depthBits);
      glGetNamedRenderbufferParameteriv(layout.depthStencilRenderbuffer, GL_RENDERBUFFER_SAMPLES, &samples);
    }
    if (depthBits == 0 || samples > 1)
      return Error{ErrorCode::InvalidLayout, "depthStencilRenderbuffer " +
                                                 std::to_string(layout.depthStencilRenderbuffer) +
                                                 " is no single-sample depth renderbuffer"};
    return Status::ok();
  }
  static Result<std::unique_ptr<DepthMirror>> create(PluginContext& context, const GBufferLayout& layout) {
    auto mirror = std::make_unique<DepthMirror>();
    const GLenum format = sizedDepthRenderbufferFormat(layout.depthStencilRenderbuffer);
    mirror->width = layout.width;
    mirror->height = layout.height;
    mirror->texture = makeTexture(context, format, layout.width, layout.height, 0, "depth_mirror", mirror->bytes);
    mirror->hostDepth = makeFramebuffer(context, "depth_mirror.host");
    glNamedFramebufferRenderbuffer(mirror->hostDepth.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                   layout.depthStencilRenderbuffer);
    mirror->mirrorDepth = makeFramebuffer(context, "depth_mirror.texture");
    glNamedFramebufferTexture(mirror->mirrorDepth.get(), GL_DEPTH_ATTACHMENT, mirror->texture.get(), 0);
    for (GLuint fbo : {mirror->hostDepth.get(), mirror->mirrorDepth.get()}) {
      glNamedFramebufferDrawBuffer(fbo, GL_NONE);
      glNamedFramebufferReadBuffer(fbo, GL_NONE);
      if (Status status = checkFramebuffer(fbo, "depth_mirror"); !status) return status.error();
    }
    return mirror;
  }
  // The mirror into the host's renderbuffer, or back.
  void copy(bool toHost) const {
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glBlitNamedFramebuffer(toHost ? mirrorDepth.get() : hostDepth.get(), toHost ? hostDepth.get() : mirrorDepth.get(),
                           0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
};

ContextCapabilities queryCapabilities(uint32_t disabledFeatures, int maxSamplesLimit) {
  ContextCapabilities caps;
  GLint samples = 1, colorSamples = 1, depthSamples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colorSamples);
  glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depthSamples);
  caps.maxSamples = std::max(1, std::min({samples, colorSamples, depthSamples}));
  if (maxSamplesLimit > 0) caps.maxSamples = std::min(caps.maxSamples, maxSamplesLimit);
  caps.timerQuery = (epoxy_gl_version() >= 33 || epoxy_has_gl_extension("GL_ARB_timer_query")) &&
                    !(disabledFeatures & kFeatureTimerQuery);
  caps.stencilExport =
      epoxy_has_gl_extension("GL_ARB_shader_stencil_export") && !(disabledFeatures & kFeatureStencilExport);
  caps.pipelineStatistics = (epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) &&
                            !(disabledFeatures & kFeaturePipelineStatistics);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &caps.maxTextureSize);
  return caps;
}

}  // namespace

// One technique of the running config and the registry row it was built for.
struct ActiveTechnique {
  const TechniqueRow* row = nullptr;
  std::unique_ptr<Technique> technique;
};

struct Plugin::Impl {
  PluginContext context;
  // The shared pieces, held while an active row asks for them.
  std::unique_ptr<MsaaGBuffer> msaa;
  std::unique_ptr<ResolvePass> resolvePass;  // with the MSAA G-buffer: slice 0's base, and `resolve` itself
  std::unique_ptr<SliceRenderer> slices;
  std::unique_ptr<PostTarget> postTarget;
  std::unique_ptr<ForwardTarget> forward;    // GBufferLayout::drawsForwardPasses with a multisampled G-buffer
  std::unique_ptr<ForwardMask> forwardMask;  // the same, while a technique readsForwardMask()
  // Where the frame stands: resolved (shade() may follow), shaded (beginForward() may follow), forward passes
  // drawing into the host's own target or into the multisampled forward target (endForward() may follow).
  enum class FramePhase : uint8_t { Open, Resolved, Shaded, ForwardIntoHost, ForwardMultisampled };
  FramePhase phase = FramePhase::Open;
  std::unique_ptr<DepthMirror> depthMirror;  // when the host's depth is a renderbuffer
  // The method's technique first, then the stacked ones; each pass runs them in this order.
  std::vector<ActiveTechnique> techniques;
  std::unique_ptr<BudgetController> budget;
  bool warnedMultisampleOff = false;      // once per plugin: GL_MULTISAMPLE was off at resolve()
  bool warnedFloorsUntimed = false;       // once per plugin: measure_pass_floors without measure_gpu_time
  bool warnedProjectionEncoding = false;  // once per plugin: the projection's clip z disagrees with the layout

  // A perspective projection's depth term P[3][2] is -2fn/(f-n) where clip z runs -w … w (GL's) and -fn/(f-n)
  // where it runs 0 … w (Direct3D's, Irrlicht's): the two window depths differ, and a layout that names the
  // other one decodes every depth wrong (positions, closeness, a history's reprojection). Warned once.
  void checkProjectionAgainstDepthEncoding(const FrameInfo& frame) {
    const DepthBufferEncoding declared = context.layout.depthBufferEncoding;
    const bool perspective = declared == DepthBufferEncoding::Perspective,
               zeroToOne = declared == DepthBufferEncoding::PerspectiveClipZeroToOne;
    const float n = frame.nearPlane, f = frame.farPlane, term = frame.projectionMatrix[14];
    if (warnedProjectionEncoding || !(perspective || zeroToOne) || term == 0.0f || !(f > n && n > 0.0f)) return;
    const float ratio = std::fabs(term) / (f * n / (f - n));  // 2 for GL's clip z, 1 for 0 … w
    if (!(std::isfinite(ratio) && ratio > 0.5f && ratio < 2.5f) || (ratio < 1.5f) == zeroToOne) return;
    warnedProjectionEncoding = true;
    context.warn(std::string("layout check: FrameInfo::projectionMatrix's clip z runs ") +
                 (zeroToOne ? "-w … w (GL's)" : "0 … w (Direct3D's, Irrlicht's)") + " but depthBufferEncoding is " +
                 (zeroToOne ? "PerspectiveClipZeroToOne" : "Perspective") + ": declare " +
                 (zeroToOne ? "Perspective" : "PerspectiveClipZeroToOne") +
                 ", or every depth the plugin reads is decoded wrong (docs/integration.md)");
  }
  uint64_t budgetFrame = 0;  // the measured frame the budget last saw

  // The first active technique's prepass framebuffer (0: no method draws the models a second time).
  GLuint prepassFramebuffer() const {
    for (const ActiveTechnique& active : techniques)
      if (const GLuint framebuffer = active.technique->prepassFramebuffer()) return framebuffer;
    return 0;
  }
  // Whether the host's model pass (or its prepass) draws multisampled, where sample shading means anything.
  bool drawsMultisampled() const { return (msaa && msaa->rasterisesPerSample()) || prepassFramebuffer() != 0; }
  // The materials' mip bias for draws shaded at `shading` (a fraction of the samples): a method with a history's
  // own, or, shaded per sample, -0.5 log2(k): each pixel averages k = shading × samples texture reads at the
  // pixel's mip, and the mip of a render at √k times the width and height is log2(√k) finer (at 4×, shaded
  // fully: -1); the more negative.
  float textureLodBiasShading(float shading) const {
    float history = 0.0f;  // a method with a history's own (the others' are 0)
    for (const ActiveTechnique& active : techniques) history += active.technique->textureLodBias(context.config);
    const int samples = msaa ? msaa->samples() : context.config.samples;
    return std::min(history, -0.5f * std::log2(std::max(1.0f, shading * float(samples))));
  }

  SharedTargets shared() { return {msaa.get(), resolvePass.get(), slices.get(), postTarget.get(), forwardMask.get()}; }
  Technique* methodTechnique() {
    return !techniques.empty() && techniques.front().row->info.method == context.config.method
               ? techniques.front().technique.get()
               : nullptr;
  }

  static uint32_t storageOf(const Config& config, const std::vector<const TechniqueRow*>& rows) {
    uint32_t storage = kStorageNone;
    for (const TechniqueRow* row : rows)
      storage |= row->info.method == config.method ? row->storage : row->stackedStorage;
    if (storage & kStorageSlices) storage |= kStorageMsaaGBuffer;
    return storage;
  }

  // Opens a frame's statistics; a frame whose figures came back steers the budget (a frame or two late,
  // which the controller's damping absorbs).
  void beginFrame() {
    context.statistics->beginFrame();  // reads what came back
    const FrameFigures& measured = context.statistics->latest();
    if (!budget || measured.frame == 0 || measured.frame == budgetFrame) return;
    budgetFrame = measured.frame;
    double ms = 0;
    for (const PassStats& pass : measured.passes) ms += pass.ms;
    context.budgetScale = budget->update(ms);
  }

  // Budget mode applies where the method's technique trades time for quality continuously.
  void configureBudget(const Config& previous) {
    const Config& config = context.config;
    Technique* technique = methodTechnique();
    if (config.budgetMs <= 0 || !technique || !technique->followsBudget(config)) {
      budget.reset();
      context.budgetScale = 1.0;
      if (config.budgetMs > 0 && previous.budgetMs != config.budgetMs)
        context.warn(std::string("budget_ms has no effect on ") + toString(config.method) +
                     " with these settings: its cost does not follow a quality setting (docs/tune.md lists the methods "
                     "it steers)");
    } else if (!budget || previous.budgetMs != config.budgetMs) {
      budget = std::make_unique<BudgetController>(config.budgetMs);
      context.budgetScale = budget->scale();
    }
    context.timePasses = config.measureGpuTime || budget != nullptr;
  }

  // Each measured pass's floor (measure_pass_floors, with measure_gpu_time): the recorder, on a new one
  // whenever the shader library is new.
  void configureFloors(bool newShaders) {
    const Config& config = context.config;
    if (newShaders || !(config.measurePassFloors && config.measureGpuTime)) context.floors.reset();
    if (config.measurePassFloors && !config.measureGpuTime && !warnedFloorsUntimed) {
      warnedFloorsUntimed = true;
      context.warn("measure_pass_floors=on needs measure_gpu_time=on (and timer queries): floors are not measured");
    }
    if (config.measurePassFloors && config.measureGpuTime && !context.floors)
      context.floors = std::make_unique<PassFloors>(context.objects, *context.shaders);
  }

  // Grants a requested (valid) config against the context: falls back from methods it cannot run and
  // clamps samples, each with a warning.
  Config grant(Config requested) {
    const ContextCapabilities& caps = context.capabilities;
    const MethodInfo* method = findMethod(requested.method);
    if (method->multisampled && caps.maxSamples < 2) {
      context.warn(std::string("method ") + method->name + " needs multisampling but the context's GL_MAX_SAMPLES is " +
                   std::to_string(caps.maxSamples) + "; falling back to " + toString(fallbackWithoutMultisampling()));
      requested.method = fallbackWithoutMultisampling();
      method = findMethod(requested.method);
    }
    if (const int least = findTechnique(requested.method)->minSupersample; requested.supersample < least) {
      context.warn(std::string("method ") + method->name + " renders a supersampled G-buffer and supersample=" +
                   std::to_string(requested.supersample) + "; using supersample=" + std::to_string(least));
      requested.supersample = least;
    }
    if (requested.samples < method->minSamples && caps.maxSamples >= method->minSamples) {
      context.warn(std::string("method ") + method->name + " needs at least " + std::to_string(method->minSamples) +
                   " samples, samples=" + std::to_string(requested.samples) + " requested; using " +
                   std::to_string(method->minSamples));
      requested.samples = method->minSamples;
    }
    // A stacked filter that reads the MSAA G-buffer's sub-samples has none at 1×.
    for (const TechniqueRow& row : techniqueRegistry())
      if (row.stackedOn && row.stackedOn(requested) && requested.samples < row.info.minSamples) {
        context.warn(std::string(row.info.stackKey) + " needs at least " + std::to_string(row.info.minSamples) +
                     " samples and samples=" + std::to_string(requested.samples) + "; the filter is off");
        applySetting(requested, row.info.stackKey, "off");
      } else if (row.stackedOn && row.stackedOn(requested) && row.info.minSamples > 1 && requested.supersample > 1) {
        context.warn(std::string(row.info.stackKey) + " reads a multisampled G-buffer and supersample=" +
                     std::to_string(requested.supersample) + " makes a supersampled one; the filter is off");
        applySetting(requested, row.info.stackKey, "off");
      }
    if (requested.measureGpuTime && !caps.timerQuery) {
      context.warn("measure_gpu_time=on but the context has no timer queries: pass times are not measured");
      requested.measureGpuTime = false;
    }
    if (requested.samples > caps.maxSamples) {
      if (method->multisampled)  // only worth a word when the method uses the samples
        context.warn("samples=" + std::to_string(requested.samples) + " requested, the context grants " +
                     std::to_string(caps.maxSamples) + " (GL_MAX_SAMPLES); using " + std::to_string(caps.maxSamples));
      requested.samples = caps.maxSamples;
    }
    return requested;
  }

  // Holds exactly what the active rows need: frees the rest, creates what is missing.
  Status allocate(bool rebuildAll) {
    const Config& config = context.config;
    if (context.floors) context.floors->release();  // their scratch targets follow the passes allocated here
    const std::vector<const TechniqueRow*> rows = activeTechniqueRows(config);
    const uint32_t storage = storageOf(config, rows);
    const bool needMsaa = storage & kStorageMsaaGBuffer;
    // A host's depth renderbuffer: the passes read its texture mirror, held only while any pass runs.
    if (context.layout.depthStencilRenderbuffer) {
      if (storage == kStorageNone) {
        depthMirror.reset();
      } else if (!depthMirror) {
        auto created = DepthMirror::create(context, context.layout);
        if (!created) return created.error();
        depthMirror = std::move(created.value());
      }
      context.layout.depthStencilTexture = depthMirror ? depthMirror->texture.get() : 0;
    }
    if (rebuildAll || !needMsaa ||
        (msaa &&
         (msaa->requestedSamples() != config.samples || msaa->supersample() != std::max(config.supersample, 1)))) {
      if (rebuildAll || msaa) techniques.clear();  // techniques may hold the G-buffer's or the slices' objects
      forward.reset();
      slices.reset();
      resolvePass.reset();
      msaa.reset();
    }
    if (!(storage & kStorageSlices)) slices.reset();
    if (resolvePass && resolvePass->computeRequested() != config.resolveCompute) resolvePass.reset();
    if (rebuildAll || !(storage & kStoragePostTarget)) postTarget.reset();
    if (rebuildAll) forwardMask.reset();
    std::vector<ActiveTechnique> kept;
    for (ActiveTechnique& active : techniques)
      if (std::find(rows.begin(), rows.end(), active.row) != rows.end() && active.technique->keepsObjectsFor(config))
        kept.push_back(std::move(active));
    techniques.clear();  // what is not kept is freed before anything new is allocated

    if (needMsaa && !msaa) {
      auto created = MsaaGBuffer::create(context, config.samples, config.supersample);
      if (!created) return created.error();
      msaa = std::move(created.value());
    }
    if (needMsaa && !resolvePass) {
      auto created = ResolvePass::create(context, *msaa);
      if (!created) return created.error();
      resolvePass = std::move(created.value());
    }
    const bool needForward = needMsaa && context.layout.drawsForwardPasses && msaa->rasterisesPerSample() &&
                             sceneColourTexture(context.layout);
    if (!needForward) forward.reset();
    if (needForward && !forward) {
      auto created = ForwardTarget::create(context, *msaa);
      if (!created) return created.error();
      forward = std::move(created.value());
    }
    if ((storage & kStorageSlices) && !slices) {
      auto created = SliceRenderer::create(context, *msaa);
      if (!created) return created.error();
      slices = std::move(created.value());
    }
    if ((storage & kStoragePostTarget) && !postTarget) {
      auto created = PostTarget::create(context);
      if (!created) return created.error();
      postTarget = std::move(created.value());
    }
    for (const TechniqueRow* row : rows) {
      if (!row->create) continue;
      auto existing = std::find_if(kept.begin(), kept.end(), [row](const ActiveTechnique& a) { return a.row == row; });
      if (existing != kept.end()) {
        techniques.push_back(std::move(*existing));
        continue;
      }
      SharedTargets targets = shared();
      auto created = row->create(context, targets);
      if (!created) return created.error();
      techniques.push_back({row, std::move(created.value())});
    }
    const bool needMask = std::any_of(techniques.begin(), techniques.end(),
                                      [](const ActiveTechnique& a) { return a.technique->readsForwardMask(); });
    if (!needMask) forwardMask.reset();
    if (needMask && !forwardMask) {
      auto created = ForwardMask::create(context);
      if (!created) return created.error();
      forwardMask = std::move(created.value());
    }
    return Status::ok();
  }

  // Validates `host` and makes it the layout every pass uses. A depth renderbuffer is mirrored in a
  // texture only while a method runs (allocate(): `off` holds nothing).
  Status setLayout(const GBufferLayout& host) {
    if (Status status = DepthMirror::validate(host); !status) return status;
    GBufferLayout layout = host;
    // Unsized formats (GL_RGBA, …) become the sized ones the host's textures have: the plugin's copies
    // need sized storage.
    for (Attachment& attachment : layout.attachments) {
      if (!attachment.texture) continue;  // validateLayout names it
      const GLenum sized = sizedColourFormat(attachment.texture, attachment.internalFormat);
      if (!sized) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04x", unsigned(attachment.internalFormat));
        return Error{ErrorCode::InvalidLayout, std::string("attachment ") + roleName(attachment.role) +
                                                   " has the unsized format " + hex + " and texture " +
                                                   std::to_string(attachment.texture) +
                                                   " has no sized format a copy could take (give a sized one, e.g. "
                                                   "GL_RGBA8, GL_RGBA16F)"};
      }
      attachment.internalFormat = sized;
    }
    if (Status status = validateLayout(layout); !status) return status;
    context.layout = layout;
    depthMirror.reset();
    return Status::ok();
  }

  uint64_t bytesHeld() const {
    uint64_t bytes = (msaa ? msaa->bytes() : 0) + (resolvePass ? resolvePass->bytes() : 0) +
                     (slices ? slices->bytes() : 0) + (postTarget ? postTarget->bytes() : 0) +
                     (depthMirror ? depthMirror->bytes : 0) + (forward ? forward->bytes() : 0) +
                     (forwardMask ? forwardMask->bytes() : 0);
    for (const ActiveTechnique& active : techniques) bytes += active.technique->bytes();
    return bytes;
  }
};

Plugin::Plugin(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Plugin::~Plugin() = default;

Result<std::unique_ptr<Plugin>> Plugin::create(const Description& description) {
  if (epoxy_gl_version() < 45)
    return Error{ErrorCode::UnsupportedContext, "retroaa needs an OpenGL 4.5 core context, this one is " +
                                                    std::to_string(epoxy_gl_version() / 10) + "." +
                                                    std::to_string(epoxy_gl_version() % 10)};
  if (Status status = validateConfig(description.config); !status) return status.error();
  GlStateGuard guard;
  auto impl = std::make_unique<Impl>();
  PluginContext& context = impl->context;
  if (Status status = impl->setLayout(description.layout); !status) return status.error();
  context.log = description.log;
  context.capabilities = queryCapabilities(description.disabledFeatures, description.maxSamplesLimit);
  context.capabilities.gbufferBudgetBytes = description.gbufferBudgetBytes;
  if (!context.capabilities.stencilExport)
    context.warn(
        "no ARB_shader_stencil_export: slice counts reach the stencil mask in one pass per bit of the count instead of "
        "one pass");
  context.config = impl->grant(description.config);
  context.shaders = std::make_unique<ShaderLibrary>(context.objects, context.config.shaderOverrideDirectory,
                                                    [&context](const std::string& m) { context.warn(m); });
  context.statistics =
      std::make_unique<FrameStatistics>(context.capabilities.timerQuery, context.capabilities.pipelineStatistics);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  context.emptyVertexArray = GlVertexArray(context.objects, vao);
  if (Status status = impl->allocate(true); !status) return status.error();
  impl->configureBudget(Config{});
  impl->configureFloors(false);
  return std::unique_ptr<Plugin>(new Plugin(std::move(impl)));
}

int Plugin::geometryScale() const { return impl_->msaa ? impl_->msaa->supersample() : 1; }

GLuintHandle Plugin::prepassFramebuffer() const { return impl_->prepassFramebuffer(); }

GLuintHandle Plugin::multisampledAttachment(AttachmentRole role) const {
  const int index = findRole(impl_->context.layout, role);
  return impl_->msaa && index >= 0 ? impl_->msaa->attachment(size_t(index)) : 0;
}

GLuintHandle Plugin::geometryFramebuffer() const {
  return impl_->msaa ? impl_->msaa->framebuffer() : impl_->context.layout.gbufferFramebuffer;
}

Jitter Plugin::jitter() const {
  const PluginContext& context = impl_->context;
  for (const ActiveTechnique& active : impl_->techniques)
    if (const std::optional<Jitter> offset =
            active.technique->jitter(context.config, context.statistics->framesStarted()))
      return *offset;
  return {};
}

float Plugin::sampleShading() const { return impl_->drawsMultisampled() ? impl_->context.config.sampleShading : 0.0f; }

float Plugin::textureLodBias() const { return impl_->textureLodBiasShading(sampleShading()); }

DrawSettings Plugin::cutOutDrawSettings() const {
  const Config& config = impl_->context.config;
  const float shading = impl_->drawsMultisampled() ? std::max(config.sampleShading, config.cutOutSampleShading) : 0.0f;
  return {shading, impl_->textureLodBiasShading(shading)};
}

Status Plugin::resolve(const FrameInfo& frame) {
  PluginContext& context = impl_->context;
  impl_->beginFrame();
  impl_->phase = Impl::FramePhase::Resolved;
  impl_->context.frame = frame;
  impl_->checkProjectionAgainstDepthEncoding(frame);
  if (!impl_->resolvePass) return Status::ok();
  // With GL_MULTISAMPLE off (Irrlicht turns it off on a window without MSAA) the model pass rasterised
  // single-sample: every sample holds the pixel centre's surface, or only sample 0 was written. A state
  // query, no wait; the host's state is as its model pass left it.
  if (impl_->msaa->rasterisesPerSample() && !impl_->warnedMultisampleOff && !glIsEnabled(GL_MULTISAMPLE)) {
    impl_->warnedMultisampleOff = true;
    context.warn(
        "GL_MULTISAMPLE is disabled at resolve(): the model pass rasterised into the MSAA G-buffer single-sample "
        "(no anti-aliased edges; some drivers write sample 0 only). Enable it while drawing into "
        "geometryFramebuffer() (docs/integration.md)");
  }
  GlStateGuard guard;
  SharedTargets shared = impl_->shared();
  Technique* method = impl_->methodTechnique();
  const std::optional<ResolveCounts> counts = method ? method->resolveCounts(context, shared) : std::nullopt;
  if (Status status = impl_->resolvePass->run(context, *impl_->msaa, frame, counts ? &*counts : nullptr); !status)
    return status;
  if (impl_->depthMirror) impl_->depthMirror->copy(true);  // the resolved depth into the host's renderbuffer
  for (ActiveTechnique& active : impl_->techniques)
    if (Status status = active.technique->afterResolve(context, shared, frame); !status) return status;
  return Status::ok();
}

Status Plugin::shade(const LightingFunction& lighting) {
  if (impl_->context.layout.composedFramebuffer)
    return Error{ErrorCode::InvalidLayout,
                 "the layout names a composedFramebuffer, so shade() takes a ComposingFunction (its callback composes "
                 "scene colour into ShadeTargets::composed); a LightingFunction would leave composedTexture unwritten"};
  return shade([&lighting](const ShadeTargets& targets) { lighting(targets.light); });
}

Status Plugin::shade(const ComposingFunction& compose) {
  PluginContext& context = impl_->context;
  if (impl_->phase != Impl::FramePhase::Resolved) {
    if (impl_->msaa)  // the host's G-buffer holds nothing of this frame's model pass
      return Error{ErrorCode::WrongCallOrder, std::string("shade() without resolve() since the last shade(): ") +
                                                  toString(context.config.method) +
                                                  " needs the model pass resolved first (see docs/integration.md)"};
    impl_->beginFrame();
  }
  impl_->phase = Impl::FramePhase::Shaded;
  if (impl_->forward) {
    GlStateGuard guard;
    impl_->forward->beginFrame(context);
  }
  if (impl_->forwardMask) impl_->forwardMask->clear();  // a frame without forward passes drew none
  if (impl_->slices) {
    GlStateGuard guard;
    SharedTargets shared = impl_->shared();
    Technique* technique = impl_->methodTechnique();
    const SliceRenderer::Plan plan = technique ? technique->slicePlan(context, shared) : SliceRenderer::Plan{};
    if (context.config.restoreGBufferAfterShade) impl_->resolvePass->keepForRestore(context, *impl_->slices);
    Status status = impl_->slices->shade(context, *impl_->msaa, compose, plan, impl_->forward.get());
    if (status && context.config.restoreGBufferAfterShade)
      status = impl_->resolvePass->restore(context, *impl_->msaa, impl_->context.frame, *impl_->slices);
    if (status && impl_->forward) impl_->forward->keepShadedColour(context.layout);
    return status;
  }
  // Single-slice methods light once, every pixel, in the host's own target.
  context.frameStats.slices = 1;
  {
    GlStateGuard guard;
    ScopedPass timed(context, "lighting");
    compose({context.layout.lightFramebuffer, context.layout.composedFramebuffer});
  }
  context.statistics->addEvaluations(context.pixelCount());
  GlStateGuard guard;
  SharedTargets shared = impl_->shared();
  for (ActiveTechnique& active : impl_->techniques)
    if (Status status = active.technique->afterLighting(context, shared, impl_->context.frame); !status) return status;
  return Status::ok();
}

Result<GLuintHandle> Plugin::beginForward() {
  PluginContext& context = impl_->context;
  if (impl_->phase != Impl::FramePhase::Shaded)
    return Error{ErrorCode::WrongCallOrder,
                 impl_->phase == Impl::FramePhase::Open || impl_->phase == Impl::FramePhase::Resolved
                     ? "beginForward() without shade() since the frame began"
                     : "beginForward() twice without endForward()"};
  impl_->phase = Impl::FramePhase::ForwardIntoHost;
  if (impl_->forwardMask) impl_->forwardMask->keepSceneColour(context.layout);
  if (!impl_->forward) return sceneColourFramebuffer(context.layout);
  impl_->phase = Impl::FramePhase::ForwardMultisampled;
  GlStateGuard guard;
  impl_->forward->fill(context);
  return impl_->forward->framebuffer();
}

Status Plugin::endForward() {
  const Impl::FramePhase phase = impl_->phase;
  if (phase != Impl::FramePhase::ForwardIntoHost && phase != Impl::FramePhase::ForwardMultisampled)
    return Error{ErrorCode::WrongCallOrder, "endForward() without beginForward()"};
  impl_->phase = Impl::FramePhase::Open;
  GlStateGuard guard;
  if (phase == Impl::FramePhase::ForwardMultisampled) impl_->forward->resolve(impl_->context);
  if (impl_->forwardMask) impl_->forwardMask->markChanges(impl_->context);
  return Status::ok();
}

Status Plugin::post() {
  if (!impl_->postTarget) return Status::ok();
  GlStateGuard guard;
  SharedTargets shared = impl_->shared();
  const GBufferLayout& layout = impl_->context.layout;
  // Without an MSAA G-buffer the host drew its own depth: the passes read it through the mirror.
  if (impl_->depthMirror && !impl_->msaa) impl_->depthMirror->copy(false);
  impl_->postTarget->begin(layout);
  for (ActiveTechnique& active : impl_->techniques)
    if (Status status = active.technique->post(impl_->context, shared, impl_->context.frame); !status) return status;
  impl_->postTarget->end(layout);
  return Status::ok();
}

Status Plugin::reconfigure(const Config& config) {
  if (Status status = validateConfig(config); !status) return status;
  PluginContext& context = impl_->context;
  GlStateGuard guard;
  const Config previous = context.config;
  context.config = impl_->grant(config);
  const bool newShaders = config.shaderOverrideDirectory != previous.shaderOverrideDirectory;
  if (newShaders)
    context.shaders = std::make_unique<ShaderLibrary>(context.objects, config.shaderOverrideDirectory,
                                                      [&context](const std::string& m) { context.warn(m); });
  Status status = impl_->allocate(newShaders);
  if (!status) {  // keep the plugin usable: back to what worked before, or to `off` if even that fails now
    context.config = previous;
    if (Status fallback = impl_->allocate(true); !fallback) {
      context.config = Config{};
      impl_->allocate(true);  // `off` allocates nothing: it cannot fail
      context.warn("reconfigure failed (" + status.error().message + ") and the previous config failed too (" +
                   fallback.error().message + "); the method is off");
    }
  }
  impl_->configureBudget(previous);
  impl_->configureFloors(newShaders);
  for (ActiveTechnique& active : impl_->techniques) active.technique->reconfigured(context, previous);
  // Figures measured under another config would be reported as this one's.
  if (toConfigText(context.config) != toConfigText(previous)) context.statistics->release();
  return status;
}

Status Plugin::resize(const GBufferLayout& layout) {
  GlStateGuard guard;
  if (Status status = impl_->setLayout(layout); !status) return status.error();
  impl_->context.statistics->release();
  return impl_->allocate(true);
}

const Config& Plugin::config() const { return impl_->context.config; }

Stats Plugin::stats() const {
  GlStateGuard guard;
  const PluginContext& context = impl_->context;
  context.statistics->collect();
  Stats stats = context.frameStats;
  const FrameFigures& measured = context.statistics->latest();
  stats.framesStarted = context.statistics->framesStarted();
  stats.measuredFrame = measured.frame;
  stats.lightingEvaluations = measured.lightingEvaluations;
  stats.passes = measured.passes;
  stats.method = context.config.method;
  stats.samples = 1;
  if (impl_->msaa)
    stats.samples = impl_->msaa->samples();
  else
    for (const ActiveTechnique& active : impl_->techniques)
      stats.samples = std::max(stats.samples, active.technique->samples());
  stats.pixels = context.pixelCount();
  stats.bytesHeld = impl_->bytesHeld();
  stats.glObjectsHeld = context.objects.live;
  stats.statisticsQueriesHeld = context.statistics->queriesHeld();
  stats.budgetScale = context.budgetScale;
  return stats;
}

Stats Plugin::waitForStats() {
  impl_->context.statistics->waitForLastFrame();
  return stats();
}

std::vector<uint8_t> Plugin::readSliceCounts() const {
  GlStateGuard guard;  // the read's pack alignment
  if (impl_->slices) return impl_->slices->readCounts();
  return std::vector<uint8_t>(impl_->context.pixelCount(), 1);
}

std::vector<std::string> Plugin::warnings() const { return impl_->context.warnings; }

}  // namespace retroaa
