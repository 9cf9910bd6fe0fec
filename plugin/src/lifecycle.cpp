#include "lifecycle.h"

#include "shared_constants.h"

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

// The storage the active rows ask for: a stacked row asks for its stacked storage.
uint32_t storageOf(const Config& config, const std::vector<const TechniqueRow*>& rows) {
  uint32_t storage = kStorageNone;
  for (const TechniqueRow* row : rows)
    storage |= row->info.method == config.method ? row->storage : row->stackedStorage;
  if (storage & kStorageSlices) storage |= kStorageMsaaGBuffer;
  return storage;
}

}  // namespace

Status DepthMirror::validate(const GBufferLayout& layout) {
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

Result<std::unique_ptr<DepthMirror>> DepthMirror::create(PluginContext& context, const GBufferLayout& layout) {
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

void DepthMirror::copy(bool toHost) const {
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);
  glBlitNamedFramebuffer(toHost ? mirrorDepth.get() : hostDepth.get(), toHost ? hostDepth.get() : mirrorDepth.get(), 0,
                         0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

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

// Grants a requested (valid) config against the context: falls back from methods it cannot run and
// clamps samples, each with a warning.
Config Plugin::Impl::grant(Config requested) {
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

// Validates `host` and makes it the layout every pass uses. A depth renderbuffer is mirrored in a
// texture only while a method runs (allocate(): `off` holds nothing).
Status Plugin::Impl::setLayout(const GBufferLayout& host) {
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
  context.lightsIntoFloats = holdsFloats(layout.lightTexture);
  depthMirror.reset();
  return Status::ok();
}

// Holds exactly what the active rows need: frees the rest, creates what is missing.
Status Plugin::Impl::allocate(bool rebuildAll) {
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
  if (resolvePass &&
      (resolvePass->computeRequested() != config.resolveCompute || resolvePass->weighting() != config.resolveWeighting))
    resolvePass.reset();
  if (rebuildAll || !(storage & kStoragePostTarget)) postTarget.reset();
  if (rebuildAll) forwardMask.reset();
  std::vector<ActiveTechnique> kept;
  const size_t previousCount = techniques.size();
  for (ActiveTechnique& active : techniques)
    if (std::find(rows.begin(), rows.end(), active.row) != rows.end() && active.technique->keepsObjectsFor(config))
      kept.push_back(std::move(active));
  techniques.clear();  // what is not kept is freed before anything new is allocated
  // What the resolve holds for the techniques (counting programs, kept copies) follows them: freed when one
  // is added, dropped or rebuilt, kept across a change of per-frame keys alone.
  if (resolvePass && (kept.size() != previousCount || kept.size() != rows.size())) resolvePass->releaseForNewConfig();

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

// Budget mode applies where the method's technique trades time for quality continuously.
void Plugin::Impl::configureBudget(const Config& previous) {
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
void Plugin::Impl::configureFloors(bool newShaders) {
  const Config& config = context.config;
  if (newShaders || !(config.measurePassFloors && config.measureGpuTime)) context.floors.reset();
  if (config.measurePassFloors && !config.measureGpuTime && !warnedFloorsUntimed) {
    warnedFloorsUntimed = true;
    context.warn("measure_pass_floors=on needs measure_gpu_time=on (and timer queries): floors are not measured");
  }
  if (config.measurePassFloors && config.measureGpuTime && !context.floors)
    context.floors = std::make_unique<PassFloors>(context.objects, *context.shaders);
}

uint64_t Plugin::Impl::bytesHeld() const {
  uint64_t bytes = (msaa ? msaa->bytes() : 0) + (resolvePass ? resolvePass->bytes() : 0) +
                   (slices ? slices->bytes() : 0) + (postTarget ? postTarget->bytes() : 0) +
                   (depthMirror ? depthMirror->bytes : 0) + (forward ? forward->bytes() : 0) +
                   (forwardMask ? forwardMask->bytes() : 0);
  for (const ActiveTechnique& active : techniques) bytes += active.technique->bytes();
  return bytes;
}

}  // namespace retroaa
