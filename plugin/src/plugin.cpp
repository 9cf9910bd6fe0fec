// The public calls of a frame, each under a GL state guard; what the plugin holds and how it comes to
// hold it is lifecycle.cpp's.
#include "retroaa/plugin.h"

#include "gl_state.h"
#include "lifecycle.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace retroaa {

// Opens a frame's statistics; a frame whose figures came back steers the budget (a frame or two late,
// which the controller's damping absorbs).
void Plugin::Impl::beginFrame() {
  {
    GlStateGuard guard;                // the reads go to client memory, not to a host's query buffer
    context.statistics->beginFrame();  // reads what came back
  }
  const FrameFigures& measured = context.statistics->latest();
  if (!budget || measured.frame == 0 || measured.frame == budgetFrame) return;
  budgetFrame = measured.frame;
  double ms = 0;
  for (const PassStats& pass : measured.passes) ms += pass.ms;
  context.budgetScale = budget->update(ms);
}

// A perspective projection's depth term P[3][2] is -2fn/(f-n) where clip z runs -w … w (GL's) and -fn/(f-n)
// where it runs 0 … w (Direct3D's, Irrlicht's): the two window depths differ, and a layout that names the
// other one decodes every depth wrong (positions, closeness, a history's reprojection). Warned once.
void Plugin::Impl::checkProjectionAgainstDepthEncoding(const FrameInfo& frame) {
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

// The first active technique's prepass framebuffer (0: no method draws the models a second time).
GLuint Plugin::Impl::prepassFramebuffer() const {
  for (const ActiveTechnique& active : techniques)
    if (const GLuint framebuffer = active.technique->prepassFramebuffer()) return framebuffer;
  return 0;
}

// The materials' mip bias for draws shaded at `shading` (a fraction of the samples): a method with a history's
// own, or, shaded per sample, -0.5 log2(k): each pixel averages k = shading × samples texture reads at the
// pixel's mip, and the mip of a render at √k times the width and height is log2(√k) finer (at 4×, shaded
// fully: -1); the more negative.
float Plugin::Impl::textureLodBiasShading(float shading) const {
  float history = 0.0f;  // a method with a history's own (the others' are 0)
  for (const ActiveTechnique& active : techniques) history += active.technique->textureLodBias(context.config);
  const int samples = msaa ? msaa->samples() : context.config.samples;
  return std::min(history, -0.5f * std::log2(std::max(1.0f, shading * float(samples))));
}

Status Plugin::Impl::afterLighting() {
  SharedTargets targets = shared();
  for (ActiveTechnique& active : techniques)
    if (Status status = active.technique->afterLighting(context, targets, context.frame); !status) return status;
  return Status::ok();
}

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
  const float wholeScreen[4] = {-1.0f, -1.0f, 3.0f, 3.0f};
  uint64_t rectangleBytes = 0;
  context.wholeScreenRectangle = makeBuffer(context, sizeof wholeScreen, wholeScreen, "whole_screen", rectangleBytes);
  context.wholeScreenVertexArray = makeRectangleArray(context, context.wholeScreenRectangle.get(), "whole_screen");
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
  const bool depthForRestore = impl_->slices && ResolvePass::restoreNeedsDepthFloats(context, *impl_->slices);
  if (Status status =
          impl_->resolvePass->run(context, *impl_->msaa, frame, counts ? &*counts : nullptr, depthForRestore);
      !status)
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
    // The composited light is the frame's light, as one slice's would be: a history accumulates it here.
    if (status) status = impl_->afterLighting();
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
  return impl_->afterLighting();
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
  stats.lightingEvaluationsBySlice = measured.lightingEvaluationsBySlice;
  stats.lightingEvaluations =
      std::accumulate(stats.lightingEvaluationsBySlice.begin(), stats.lightingEvaluationsBySlice.end(), uint64_t(0));
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
  {
    GlStateGuard guard;  // the reads go to client memory, not to a host's query buffer
    impl_->context.statistics->waitForLastFrame();
  }
  return stats();
}

std::vector<uint8_t> Plugin::readSliceCounts() const {
  GlStateGuard guard;  // the read's pack alignment
  if (impl_->slices) return impl_->slices->readCounts();
  return std::vector<uint8_t>(impl_->context.pixelCount(), 1);
}

std::vector<std::string> Plugin::warnings() const { return impl_->context.warnings; }

}  // namespace retroaa
