#include "retroaa/plugin.h"

#include "context.h"
#include "budget_controller.h"
#include "gl_state.h"
#include "methods/methods.h"

namespace retroaa {

namespace {

bool needsMultisampledGBuffer(Method method) { return usesMsaa(method); }
bool needsSlices(Method method) {
  return method == Method::Edge || method == Method::PerSample || method == Method::Adaptive || method == Method::Aggregate;
}
bool needsEdgeMask(Method method) { return method == Method::Edge || method == Method::PerSample; }
EdgeDetector detectorFor(const Config& config) {
  return config.method == Method::PerSample ? EdgeDetector::EveryPixel : config.edgeDetector;
}
bool needsFxaa(const Config& config) { return config.method == Method::Fxaa || config.fxaa; }
bool needsCoverage(const Config& config) {
  return config.method == Method::Coverage || (config.coverageFilter && usesMsaa(config.method));
}

Status validateLayout(const GBufferLayout& layout) {
  auto invalid = [](const std::string& message) { return Error{ErrorCode::InvalidLayout, message}; };
  if (layout.width <= 0 || layout.height <= 0)
    return invalid("layout size " + std::to_string(layout.width) + "x" + std::to_string(layout.height) + " is empty");
  if (layout.attachments.empty() || layout.attachments.size() > 8)
    return invalid("layout has " + std::to_string(layout.attachments.size()) + " attachments (allowed: 1..8)");
  int positions = 0;
  for (const Attachment& a : layout.attachments) {
    if (!a.texture || !a.internalFormat) return invalid("an attachment has no texture or no format");
    positions += a.role == AttachmentRole::ViewPosition;
  }
  if (positions != 1) return invalid("layout needs exactly one ViewPosition attachment (has " + std::to_string(positions) + ")");
  if (layout.depthChannel < 0 || layout.depthChannel > 3) return invalid("depthChannel must be 0..3");
  if (!layout.gbufferFramebuffer || !layout.depthStencilTexture || !layout.lightFramebuffer || !layout.lightTexture ||
      !layout.displayFramebuffer || !layout.displayTexture)
    return invalid("layout is missing a host framebuffer or texture (gbuffer, depth-stencil, light, display)");
  return Status::ok();
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
  return caps;
}

}  // namespace

struct Plugin::Impl {
  PluginContext context;
  std::unique_ptr<MsaaGBuffer> msaa;
  std::unique_ptr<ResolvePass> resolvePass;
  std::unique_ptr<SliceRenderer> slices;
  std::unique_ptr<EdgeMask> edgeMask;
  std::unique_ptr<AdaptivePass> adaptive;
  std::unique_ptr<AggregatePass> aggregate;
  std::unique_ptr<FxaaPass> fxaaPass;
  std::unique_ptr<CoveragePass> coverage;
  std::unique_ptr<PostTarget> postTarget;
  bool coverageOwnPrepass = false;  // what `coverage` was built for
  int coverageSamples = 0;
  FrameInfo lastFrame;  // from resolve(), for post()
  std::unique_ptr<BudgetController> budget;

  // Budget mode applies where a setting trades time for quality continuously.
  bool budgetApplies(const Config& config) const {
    return config.budgetMs > 0 && (config.method == Method::Adaptive ||
                                   (config.method == Method::Edge && config.edgeDetector == EdgeDetector::Depth));
  }
  void configureBudget(const Config& previous) {
    const Config& config = context.config;
    if (!budgetApplies(config)) {
      budget.reset();
      context.budgetScale = 1.0;
      if (config.budgetMs > 0 && previous.budgetMs != config.budgetMs)
        context.warn(std::string("budget_ms applies to adaptive and to edge with the depth detector, not to ") + toString(config.method));
    } else if (!budget || previous.budgetMs != config.budgetMs) {
      budget = std::make_unique<BudgetController>(config.budgetMs);
      context.budgetScale = budget->scale();
    }
    context.timePasses = config.measureGpuTime || budget != nullptr;
  }
  bool resolvedThisFrame = false;
  int aggregateCount_ = 0;  // the c the aggregate shaders were built for

  // Grants a requested config against the context: falls back from methods it cannot run and clamps
  // samples, each with a warning.
  Config grant(Config requested) {
    if ((usesMsaa(requested.method) || requested.method == Method::Coverage) && context.capabilities.maxSamples < 2) {
      context.warn(std::string("method ") + toString(requested.method) + " needs multisampling but the context's GL_MAX_SAMPLES is " +
                   std::to_string(context.capabilities.maxSamples) + "; falling back to fxaa");
      requested.method = Method::Fxaa;
    }
    if (requested.method == Method::Coverage && requested.samples < 2 && context.capabilities.maxSamples >= 2) {
      context.warn("method coverage needs at least 2 depth samples, samples=" + std::to_string(requested.samples) +
                   " requested; using 2");
      requested.samples = 2;
    }
    if (requested.coverageFilter && usesMsaa(requested.method) && requested.samples < 2) {
      context.warn("coverage_filter needs at least 2 samples and samples=" + std::to_string(requested.samples) +
                   "; the filter is off");
      requested.coverageFilter = false;
    }
    if (requested.measureGpuTime && !context.capabilities.timerQuery) {
      context.warn("measure_gpu_time=on but the context has no timer queries: pass times are not measured");
      requested.measureGpuTime = false;
    }
    if (requested.samples > context.capabilities.maxSamples) {
      // Only worth a word when the method uses the samples.
      if (usesMsaa(requested.method) || requested.method == Method::Coverage)
        context.warn("samples=" + std::to_string(requested.samples) + " requested, the context grants " +
                     std::to_string(context.capabilities.maxSamples) + " (GL_MAX_SAMPLES); using " +
                     std::to_string(context.capabilities.maxSamples));
      requested.samples = context.capabilities.maxSamples;
    }
    return requested;
  }

  // Holds exactly what the configured method needs: frees the rest, creates what is missing.
  Status allocate(bool rebuildAll) {
    const Config& config = context.config;
    if (rebuildAll || !needsMultisampledGBuffer(config.method) || (msaa && msaa->requestedSamples() != config.samples)) {
      edgeMask.reset();
      coverage.reset();
      adaptive.reset();
      aggregate.reset();
      slices.reset();
      resolvePass.reset();
      msaa.reset();
    }
    if (!needsEdgeMask(config.method) || (edgeMask && edgeMask->detector() != detectorFor(config))) edgeMask.reset();
    if (config.method != Method::Adaptive) adaptive.reset();
    if (config.method != Method::Aggregate || (aggregate && aggregateCount_ != config.aggregateCount)) aggregate.reset();
    if (!needsSlices(config.method)) slices.reset();
    if (rebuildAll || !needsFxaa(config)) fxaaPass.reset();
    const bool ownPrepass = config.method == Method::Coverage;
    if (!needsCoverage(config) || ownPrepass != coverageOwnPrepass || (ownPrepass && coverageSamples != config.samples))
      coverage.reset();
    if (rebuildAll || !(needsFxaa(config) || needsCoverage(config))) postTarget.reset();
    if (needsMultisampledGBuffer(config.method) && !msaa) {
      auto created = MsaaGBuffer::create(context, config.samples);
      if (!created) return created.error();
      msaa = std::move(created.value());
    }
    if (needsMultisampledGBuffer(config.method) && !resolvePass) {  // the resolved G-buffer is slice 0's base
      auto created = ResolvePass::create(context, *msaa);
      if (!created) return created.error();
      resolvePass = std::move(created.value());
    }
    if (needsSlices(config.method) && !slices) {
      auto created = SliceRenderer::create(context, *msaa);
      if (!created) return created.error();
      slices = std::move(created.value());
    }
    if (config.method == Method::Adaptive && !adaptive) {
      auto created = AdaptivePass::create(context, *msaa, context.capabilities.stencilExport);
      if (!created) return created.error();
      adaptive = std::move(created.value());
    }
    if (config.method == Method::Aggregate && !aggregate) {
      auto created = AggregatePass::create(context, *msaa, *slices, context.capabilities.stencilExport);
      if (!created) return created.error();
      aggregate = std::move(created.value());
      aggregateCount_ = config.aggregateCount;
    }
    if (needsEdgeMask(config.method) && !edgeMask) {
      auto created = EdgeMask::create(context, *msaa, detectorFor(config), context.capabilities.stencilExport);
      if (!created) return created.error();
      edgeMask = std::move(created.value());
    }
    if ((needsFxaa(config) || needsCoverage(config)) && !postTarget) {
      auto created = PostTarget::create(context);
      if (!created) return created.error();
      postTarget = std::move(created.value());
    }
    if (needsCoverage(config) && !coverage) {
      auto created = CoveragePass::create(context, ownPrepass ? nullptr : msaa.get(), config.samples);
      if (!created) return created.error();
      coverage = std::move(created.value());
      coverageOwnPrepass = ownPrepass;
      coverageSamples = config.samples;
    }
    if (needsFxaa(config) && !fxaaPass) {
      auto created = FxaaPass::create(context);
      if (!created) return created.error();
      fxaaPass = std::move(created.value());
    }
    return Status::ok();
  }

  uint64_t bytesHeld() const {
    return (msaa ? msaa->bytes() : 0) + (slices ? slices->bytes() : 0) + (adaptive ? adaptive->bytes() : 0) +
           (aggregate ? aggregate->bytes() : 0) +
           (coverage ? coverage->bytes() : 0) + (postTarget ? postTarget->bytes() : 0);
  }
};

Plugin::Plugin(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Plugin::~Plugin() = default;

Result<std::unique_ptr<Plugin>> Plugin::create(const Description& description) {
  if (epoxy_gl_version() < 45)
    return Error{ErrorCode::UnsupportedContext, "retroaa needs an OpenGL 4.5 core context, this one is " +
                                                    std::to_string(epoxy_gl_version() / 10) + "." +
                                                    std::to_string(epoxy_gl_version() % 10)};
  if (Status status = validateLayout(description.layout); !status) return status.error();
  GlStateGuard guard;
  auto impl = std::make_unique<Impl>();
  PluginContext& context = impl->context;
  context.layout = description.layout;
  context.log = description.log;
  context.capabilities = queryCapabilities(description.disabledFeatures, description.maxSamplesLimit);
  if (!context.capabilities.stencilExport)
    context.warn("no ARB_shader_stencil_export: slice counts reach the stencil mask in N passes instead of one");
  context.config = impl->grant(description.config);
  context.shaders = std::make_unique<ShaderLibrary>(context.objects, context.config.shaderOverrideDirectory,
                                                    [&context](const std::string& m) { context.warn(m); });
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  context.emptyVertexArray = GlVertexArray(context.objects, vao);
  if (Status status = impl->allocate(true); !status) return status.error();
  impl->configureBudget(Config{});
  return std::unique_ptr<Plugin>(new Plugin(std::move(impl)));
}

GLuintHandle Plugin::coverageFramebuffer() const {
  return impl_->coverage ? impl_->coverage->prepassFramebuffer() : 0;
}

GLuintHandle Plugin::geometryFramebuffer() const {
  return impl_->msaa ? impl_->msaa->framebuffer() : impl_->context.layout.gbufferFramebuffer;
}

Status Plugin::resolve(const FrameInfo& frame) {
  PluginContext& context = impl_->context;
  context.frameStats.passes.clear();
  context.frameStats.lightingEvaluations = 0;
  impl_->resolvedThisFrame = true;
  impl_->lastFrame = frame;
  if (!impl_->resolvePass) return Status::ok();
  GlStateGuard guard;
  if (Status status = impl_->resolvePass->run(context, *impl_->msaa, frame); !status) return status;
  if (impl_->edgeMask) return impl_->edgeMask->run(context, *impl_->msaa, *impl_->slices, frame);
  if (impl_->adaptive) return impl_->adaptive->measureGeometry(context, *impl_->msaa, frame);
  if (impl_->aggregate) return impl_->aggregate->cluster(context, *impl_->msaa, *impl_->slices, frame);
  return Status::ok();
}

Status Plugin::shade(const LightingFunction& lighting) {
  PluginContext& context = impl_->context;
  if (!impl_->resolvedThisFrame) {
    context.frameStats.passes.clear();
    context.frameStats.lightingEvaluations = 0;
  }
  impl_->resolvedThisFrame = false;
  if (impl_->slices) {
    GlStateGuard guard;
    SliceRenderer::Plan plan;
    if (impl_->adaptive) plan = impl_->adaptive->plan(context, *impl_->slices);
    if (impl_->aggregate) plan = impl_->aggregate->plan(context, *impl_->msaa);
    const Status status = impl_->slices->shade(context, *impl_->msaa, lighting, plan);
    if (impl_->budget) {  // the plugin's time this frame decides the next frame's refinement
      double ms = 0;
      for (const PassTime& pass : context.frameStats.passes) ms += pass.ms;
      context.budgetScale = impl_->budget->update(ms);
    }
    return status;
  }
  // Single-slice methods light once, every pixel, in the host's own target.
  context.frameStats.slices = 1;
  {
    GlStateGuard guard;
    lighting(context.layout.lightFramebuffer);
  }
  context.frameStats.lightingEvaluations += context.pixelCount();
  return Status::ok();
}

Status Plugin::post() {
  if (!impl_->postTarget) return Status::ok();
  GlStateGuard guard;
  if (impl_->coverage) {
    if (Status status = impl_->coverage->run(impl_->context, *impl_->postTarget, impl_->lastFrame); !status) return status;
  }
  if (impl_->fxaaPass) return impl_->fxaaPass->run(impl_->context, *impl_->postTarget);
  return Status::ok();
}

Status Plugin::reconfigure(const Config& config) {
  PluginContext& context = impl_->context;
  GlStateGuard guard;
  const Config previous = context.config;
  context.config = impl_->grant(config);
  const bool rebuild = config.shaderOverrideDirectory != previous.shaderOverrideDirectory ||
                       config.fxaaQuality != previous.fxaaQuality;
  if (config.shaderOverrideDirectory != previous.shaderOverrideDirectory)
    context.shaders = std::make_unique<ShaderLibrary>(context.objects, config.shaderOverrideDirectory,
                                                      [&context](const std::string& m) { context.warn(m); });
  Status status = impl_->allocate(rebuild);
  if (!status) {  // keep the plugin usable: fall back to what worked before
    context.config = previous;
    impl_->allocate(true);
  }
  impl_->configureBudget(previous);
  return status;
}

Status Plugin::resize(const GBufferLayout& layout) {
  if (Status status = validateLayout(layout); !status) return status.error();
  GlStateGuard guard;
  impl_->context.layout = layout;
  return impl_->allocate(true);
}

const Config& Plugin::config() const { return impl_->context.config; }

Stats Plugin::stats() const {
  const PluginContext& context = impl_->context;
  Stats stats = context.frameStats;
  stats.method = context.config.method;
  stats.samples = impl_->msaa ? impl_->msaa->samples() : (impl_->coverage ? impl_->coverage->samples() : 1);
  stats.pixels = context.pixelCount();
  stats.bytesHeld = impl_->bytesHeld();
  stats.glObjectsHeld = context.objects.live;
  stats.budgetScale = context.budgetScale;
  return stats;
}

std::vector<uint8_t> Plugin::readSliceCounts() const {
  if (impl_->slices) return impl_->slices->readCounts();
  return std::vector<uint8_t>(impl_->context.pixelCount(), 1);
}

std::vector<std::string> Plugin::warnings() const { return impl_->context.warnings; }

}  // namespace retroaa
