// retroaa: retrofit anti-aliasing for OpenGL deferred renderers.
//
// Placement in the host's frame (docs/integration.md has the FreeSpace Open call sites):
//
//   host G-buffer setup ──► Plugin::create / resize(layout)
//   bind geometryFramebuffer() ──► host model pass (unchanged shaders)
//   resolve(frame)          ──► MSAA → host's single-sample G-buffer (or slices)
//   shade(lighting)         ──► host lighting pass (unchanged shaders), once per slice
//     or shade(compose)     ──► host lighting + combine + sky + fog, once per slice (composedFramebuffer)
//   beginForward()          ──► host forward passes (transparents, particles, gizmos) into the framebuffer
//   endForward()                it returns: multisampled over the MSAA G-buffer's depth where there is one
//   host tonemap
//   post()                  ──► the post filters on the host's display target (the method's own, then
//                               the stacked +filters; which methods have one: methodTable())
//
// Rules: a current GL 4.5 core context on the calling thread; every call restores the GL state it
// changed (bindings, viewport, blend, depth, stencil, program, ...), so a host with a GL state cache
// is never surprised; destroy the Plugin while its context is current. Two plugins in one process
// are independent: there is no global state.
#pragma once

#include "retroaa/config.h"
#include "retroaa/export.h"
#include "retroaa/result.h"
#include "retroaa/types.h"
#include "retroaa/version.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace retroaa {

class RETROAA_API Plugin {
 public:
  // Fails with InvalidConfig (a field the text parser would refuse: validateConfig), InvalidLayout,
  // UnsupportedContext (below GL 4.5), IncompleteFramebuffer (the driver refused a target built from
  // the layout's formats) or ShaderError (a built-in shader does not build, or lacks a uniform).
  // Features the context lacks make the plugin fall back, with a warning that says which and why:
  // no multisampling (GL_MAX_SAMPLES < 2) → every multi-sample method falls back (MethodInfo::multisampled); no stencil
  // export → slice counts in ⌈log2(N+1)⌉ bit passes; no timer queries → no pass times; no pipeline statistics → no
  // invocation counts. Compute shaders run only where asked for (resolve_compute, reconstruct_compute; without image
  // stores for a target, the full-screen pass, with a warning).
  static Result<std::unique_ptr<Plugin>> create(const Description& description);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  // The framebuffer the host's model pass renders into: the plugin's MSAA G-buffer for
  // multi-sample methods, the host's own otherwise.
  GLuintHandle geometryFramebuffer() const;
  // How many times the layout's width and height the model pass renders at into geometryFramebuffer():
  // m with `supersample` = m for a G-buffer method, else 1. Set the viewport to it; projection unchanged.
  int geometryScale() const;
  // The multisampled texture behind the first attachment with `role` (GL_TEXTURE_2D_MULTISAMPLE, the
  // host's format, stats().samples samples), for a host that draws into the G-buffer between the model
  // pass and resolve() (decals) through a framebuffer of its own. 0 when the method has no MSAA G-buffer
  // or the layout no such role. Valid until the next reconfigure() or resize(): a new method or sample
  // count may replace it.
  GLuintHandle multisampledAttachment(AttachmentRole role) const;
  // For a method with a prepass (docs/methods/ says which): a multisampled framebuffer the host draws its models into
  // once more, after the model pass, with its own model shaders and colour writes on. Clear its depth to the far value
  // and its draw buffers 0 … K−1 (K: the layout's attachments) to 0 first. Its depth is always kept; a prepass that
  // filters with normals also keeps the output at the NormalGloss attachment's location (every other draw buffer is
  // GL_NONE). 0 when the method needs no such pass. Valid until the next reconfigure() or resize().
  GLuintHandle prepassFramebuffer() const;
  // Where a method with a history runs (as the method or stacked): this frame's sub-pixel offset of the projection,
  // Halton (2, 3) over temporal_jitter_length frames, narrowed to temporal_moving_jitter_scale of it with the share
  // of pixels whose history is shorter than the sequence (as textureLodBias()); (0, 0) otherwise. Call it once before
  // the model pass and shift the projection every pass of the frame that draws the scene (model pass, prepass,
  // lighting, forward passes between beginForward() and endForward(), a sky drawn late) by it:
  //   projection[2][0] += 2 * jitter.x / width;  projection[2][1] += 2 * jitter.y / height;
  // (column-major; width and height of the layout). FrameInfo::projectionMatrix stays unshifted.
  Jitter jitter() const;
  // The mip bias to add to the host's material texture samplers while this method runs: where
  // a method with a history runs, temporal_lod_bias while the view is still (the history averages the sharper mips'
  // detail over the jitter, as FSR 2 advises for native-resolution AA), moving to temporal_moving_lod_bias with the
  // share of pixels whose history is shorter than the jitter sequence (counted by the pass, read frames later: ask
  // every frame); where the model pass is shaded per sample (sampleShading() > 0),
  // -0.5 log2(the samples shaded a pixel), since each pixel averages that many reads of the pixel's own mip
  // (-1 at 4×); the more negative of the two; 0 otherwise.
  float textureLodBias() const;
  // The fraction of each pixel's samples the model pass should shade (Config::sampleShading) where the method
  // draws it multisampled (into geometryFramebuffer() or prepassFramebuffer()); 0 otherwise. Where it is above
  // 0, enable GL_SAMPLE_SHADING with glMinSampleShading(it) around those draws (and disable it after): the
  // host's `discard` then runs per sample, so cut-out (alpha-tested) edges are anti-aliased, at up to
  // `samples` times the model pass's fragment work.
  float sampleShading() const;
  // What to set around the model pass's cut-out draws instead (a fragment shader that discards: alpha-tested
  // foliage, fences, grates), for a host that can tell them apart: sample shading at
  // max(sample_shading, cutout_sample_shading) where the method draws multisampled, and the mip bias that goes
  // with it (as textureLodBias()). The cut-outs' edges are then anti-aliased for the cost of those draws alone.
  DrawSettings cutOutDrawSettings() const;
  // After the model pass, every frame and for every method (it also begins the frame). Returns the
  // first error of a pass (none are expected once create succeeded).
  Status resolve(const FrameInfo& frame);
  // Runs `lighting` once per slice and composites; for single-slice methods, once into the host's
  // light framebuffer. Errors: WrongCallOrder when a method with an MSAA G-buffer is shaded without
  // resolve() since the previous shade() (the host's G-buffer would hold nothing of this frame);
  // InvalidLayout where the layout names a composedFramebuffer (its callback composes: the overload below).
  Status shade(const LightingFunction& lighting);
  // The same for a host whose callback turns the G-buffer into scene colour (GBufferLayout::composedFramebuffer:
  // lighting, then a combine, a sky, fog): `compose` runs once per slice with that slice's targets and the
  // plugin composites what it composed. With no composedFramebuffer in the layout it composes nothing
  // (ShadeTargets::composed is 0) and acts as shade(lighting).
  Status shade(const ComposingFunction& compose);
  // After shade(), before the host's forward passes (transparents, particles, gizmos, a sky drawn late): the
  // framebuffer to draw them into. Where the layout says it draws forward passes (drawsForwardPasses) and the
  // method has a multisampled G-buffer, a multisampled copy of the scene
  // colour (RGBA16F; each sample its own slice's colour, or its pixel's) over the G-buffer's own multisampled
  // depth-stencil: forward geometry is rasterised and depth-tested per sample (enable GL_MULTISAMPLE), so its edges,
  // and the opaque silhouettes it passes behind, come out anti-aliased. Elsewhere the layout's own scene colour
  // framebuffer (composedFramebuffer, else lightFramebuffer): forward passes draw as they always did. Then
  // endForward(). Errors: WrongCallOrder without shade() since resolve() in this frame.
  Result<GLuintHandle> beginForward();
  // After the forward passes: the multisampled copy's per-pixel mean into the scene colour (nothing when
  // beginForward() returned the host's own framebuffer), and where coverage or reconstruct runs, the mask of
  // the pixels the forward passes changed. WrongCallOrder without beginForward().
  Status endForward();
  // After the host's tonemap, on the display target: each running technique's post pass, the method's own
  // first, then the stacked ones in the registry's order (src/registry.cpp), the one marked postPassLast
  // (fxaa) after the rest: `temporal+smaa` runs temporal, then smaa.
  // Nothing when the method has no post pass.
  Status post();

  // Diagnostics: the per-pixel lighting evaluation count of the last frame (slice count; 1 for
  // single-slice methods), rows bottom-up as GL stores them. Reads back from the GPU.
  std::vector<uint8_t> readSliceCounts() const;

  // Applies a new config; reallocates only what the new method needs. Errors: InvalidConfig (nothing
  // changes), or an allocation error (the previous config stays, or `off` if even that fails now).
  Status reconfigure(const Config& config);
  // The host recreated its targets (window resize). Errors: InvalidLayout, IncompleteFramebuffer.
  Status resize(const GBufferLayout& layout);

  const Config& config() const;  // as granted (samples clamped, fallbacks applied)
  // Never waits for the GPU: the counted figures (lighting evaluations, pass times and invocations) are
  // those of the newest frame whose queries are back, Stats::measuredFrame, usually a frame or two
  // behind. Safe to call every frame.
  Stats stats() const;
  // Waits until the GPU has finished the last frame begun and returns its figures (measuredFrame ==
  // framesStarted). For tools and tests between frames, not for a frame loop: it stalls the pipeline.
  Stats waitForStats();
  std::vector<std::string> warnings() const;  // every warning since creation, oldest first

 private:
  struct Impl;
  explicit Plugin(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace retroaa
