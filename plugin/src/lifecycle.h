// What a Plugin holds and how it comes to hold it: the config granted against the context, exactly the
// shared pieces and techniques the active registry rows ask for (allocate: frees the rest first, then
// creates what is missing), and the host's layout validated. The frame's calls are plugin.cpp's.
#pragma once

#include "retroaa/plugin.h"

#include "budget_controller.h"
#include "context.h"
#include "technique.h"

#include <memory>
#include <vector>

namespace retroaa {

// A host's depth renderbuffer (GBufferLayout::depthStencilRenderbuffer) mirrored in a texture of the
// same format, which every pass then uses as the host's depth texture. Depth only: the host's stencil
// stays the host's.
struct DepthMirror {
  GlTexture texture;
  GlFramebuffer hostDepth, mirrorDepth;
  int width = 0, height = 0;
  uint64_t bytes = 0;

  static Status validate(const GBufferLayout& layout);
  static Result<std::unique_ptr<DepthMirror>> create(PluginContext& context, const GBufferLayout& layout);
  // The mirror into the host's renderbuffer, or back.
  void copy(bool toHost) const;
};

// The context's limits, less the features a Description disables (tests of the fallbacks).
ContextCapabilities queryCapabilities(uint32_t disabledFeatures, int maxSamplesLimit);

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
  std::unique_ptr<DepthMirror> depthMirror;  // when the host's depth is a renderbuffer
  // The method's technique first, then the stacked ones; each pass runs them in this order.
  std::vector<ActiveTechnique> techniques;
  std::unique_ptr<BudgetController> budget;
  uint64_t budgetFrame = 0;  // the measured frame the budget last saw
  // Where the frame stands: resolved (shade() may follow), shaded (beginForward() may follow), forward passes
  // drawing into the host's own target or into the multisampled forward target (endForward() may follow).
  enum class FramePhase : uint8_t { Open, Resolved, Shaded, ForwardIntoHost, ForwardMultisampled };
  FramePhase phase = FramePhase::Open;
  bool warnedMultisampleOff = false;      // once per plugin: GL_MULTISAMPLE was off at resolve()
  bool warnedFloorsUntimed = false;       // once per plugin: measure_pass_floors without measure_gpu_time
  bool warnedProjectionEncoding = false;  // once per plugin: the projection's clip z disagrees with the layout

  // The lifecycle (lifecycle.cpp).
  // Validates `host` and makes it the layout every pass uses. A depth renderbuffer is mirrored in a
  // texture only while a method runs (allocate(): `off` holds nothing).
  Status setLayout(const GBufferLayout& host);
  // Grants a requested (valid) config against the context: falls back from methods it cannot run and
  // clamps samples, each with a warning.
  Config grant(Config requested);
  // Holds exactly what the active rows need: frees the rest, creates what is missing.
  Status allocate(bool rebuildAll);
  // Budget mode applies where the method's technique trades time for quality continuously.
  void configureBudget(const Config& previous);
  // Each measured pass's floor (measure_pass_floors, with measure_gpu_time): the recorder, on a new one
  // whenever the shader library is new.
  void configureFloors(bool newShaders);
  uint64_t bytesHeld() const;

  // The frame (plugin.cpp).
  // Opens a frame's statistics; a frame whose figures came back steers the budget.
  void beginFrame();
  void checkProjectionAgainstDepthEncoding(const FrameInfo& frame);
  // Each technique's pass on the frame's light, once the lighting (every slice of it) is composed.
  Status afterLighting();
  // The first active technique's prepass framebuffer (0: no method draws the models a second time).
  GLuint prepassFramebuffer() const;
  // Whether the host's model pass (or its prepass) draws multisampled, where sample shading means anything.
  bool drawsMultisampled() const { return (msaa && msaa->rasterisesPerSample()) || prepassFramebuffer() != 0; }
  float textureLodBiasShading(float shading) const;
  SharedTargets shared() { return {msaa.get(), resolvePass.get(), slices.get(), postTarget.get(), forwardMask.get()}; }
  Technique* methodTechnique() {
    return !techniques.empty() && techniques.front().row->info.method == context.config.method
               ? techniques.front().technique.get()
               : nullptr;
  }
};

}  // namespace retroaa
