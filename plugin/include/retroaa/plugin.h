// retroaa: retrofit anti-aliasing for OpenGL deferred renderers.
//
// Placement in the host's frame (docs/integration.md has the FreeSpace Open call sites):
//
//   host G-buffer setup ──► Plugin::create / resize(layout)
//   bind geometryFramebuffer() ──► host model pass (unchanged shaders)
//   resolve(frame)          ──► MSAA → host's single-sample G-buffer (or slices)
//   shade(lighting)         ──► host lighting pass (unchanged shaders), once per slice
//   host tonemap
//   post()                  ──► FXAA on the host's display target
//
// Rules: a current GL 4.5 core context on the calling thread; every call restores the GL state it
// changed (bindings, viewport, blend, depth, stencil, program, ...), so a host with a GL state cache
// is never surprised; destroy the Plugin while its context is current. Two plugins in one process
// are independent: there is no global state.
#pragma once

#include "retroaa/config.h"
#include "retroaa/result.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace retroaa {

using GLuintHandle = unsigned int;  // a GL object name; keeps <GL/gl.h> out of this header
using GLenumValue = unsigned int;

enum class AttachmentRole : uint8_t {
  Albedo,        // rgb albedo; averaged
  ViewPosition,  // view-space position with depth in channel `depthChannel`, encoded per DepthEncoding
  NormalGloss,   // xyz view-space normal (renormalised after averaging), w gloss (averaged apart)
  Specular,      // averaged
  Emissive,      // averaged (the sky lives here for background pixels)
  Other,         // averaged
};

// How the host stores view depth in the position attachment (distance in front of the camera, m).
struct DepthEncoding {
  enum class Kind : uint8_t {
    Linear,        // stored = d
    LogAboveKnee,  // stored = d below `knee`, knee·(1 + log2(d/knee)) above it
  };
  Kind kind = Kind::Linear;
  float knee = 8192.0f;              // metres
  float backgroundAbove = 65280.0f;  // stored values at or above this mark "no geometry"
};

// How the host maps its gloss channel (NormalGloss.w) to a specular exponent; retroaa's aggregates
// lower gloss by the spread of the normals they merge (Toksvig) in exponent space.
struct GlossEncoding {
  bool present = false;             // false: gloss is averaged like any channel
  float log2ExponentScale = 10.0f;  // exponent = exp2(gloss · scale + bias)
  float log2ExponentBias = 1.0f;
};

// How the host's depth buffer maps to view depth d (for the coverage filter).
enum class DepthBufferEncoding : uint8_t {
  Perspective,  // the rasteriser's [0,1] depth of a standard perspective projection (FreeSpace Open)
  Logarithmic,  // log2(d / near) / log2(far / near), written by the model shader
};

struct Attachment {
  AttachmentRole role = AttachmentRole::Other;
  GLenumValue internalFormat = 0;  // e.g. GL_RGBA16F; the MSAA copy uses the same
  GLuintHandle texture = 0;        // the host's single-sample texture
};

// The host's G-buffer and targets, described by role: retroaa never assumes FSO's exact layout.
struct GBufferLayout {
  int width = 0, height = 0;
  std::vector<Attachment> attachments;  // in draw-buffer order: attachment i is location i
  int depthChannel = 2;                 // channel of ViewPosition holding encoded depth
  DepthEncoding depthEncoding;
  GlossEncoding glossEncoding;
  DepthBufferEncoding depthBufferEncoding = DepthBufferEncoding::Perspective;
  GLuintHandle gbufferFramebuffer = 0;                      // the host's single-sample G-buffer (attachments + depth)
  GLuintHandle depthStencilTexture = 0;                     // DEPTH24_STENCIL8
  uint8_t hostStencilBits = 0x00;                           // stencil bits the host owns; retroaa leaves them alone
  GLuintHandle lightFramebuffer = 0;                        // where the host's lighting accumulates (RGBA16F)
  GLuintHandle lightTexture = 0;                            // its colour texture (slices composite into it)
  GLuintHandle displayFramebuffer = 0, displayTexture = 0;  // tonemapped RGBA8, for post()
};

enum class LogLevel : uint8_t { Info, Warning, Error };
using LogCallback = std::function<void(LogLevel, const std::string&)>;

// Context features the plugin uses when present. Masking one off makes the plugin behave as on a
// context without it (for testing fallbacks, or to work around a driver bug).
enum Feature : uint32_t {
  kFeatureStencilExport = 1u << 0,  // ARB_shader_stencil_export: slice counts in one pass (else N passes)
  kFeatureTimerQuery = 1u << 1,     // GL_TIME_ELAPSED: per-pass GPU times (else none reported)
};

struct Description {
  Config config;
  GBufferLayout layout;
  LogCallback log;                // receives every warning (clamps, fallbacks); may be empty
  uint32_t disabledFeatures = 0;  // Feature bits to treat as missing
  int maxSamplesLimit = 0;        // treat GL_MAX_SAMPLES as at most this (0: the context's own; 1: no MSAA)
};

// Per-frame camera facts for the closeness test.
struct FrameInfo {
  float horizontalFovRadians = 1.0f;
  float nearPlane = 0.1f, farPlane = 1e6f;  // metres, for DepthBufferEncoding
};

struct PassTime {
  std::string name;  // e.g. "resolve", "fxaa"
  double ms = 0;
};

struct Stats {
  Method method = Method::Off;
  int samples = 1;                   // samples granted (after clamping)
  uint64_t pixels = 0;               // width × height
  uint64_t lightingEvaluations = 0;  // pixels lit, summed over lighting calls of the last frame
  double evaluationsPerPixel() const { return pixels ? double(lightingEvaluations) / pixels : 0; }
  std::vector<PassTime> passes;  // plugin passes of the last frame (measureGpuTime)
  uint64_t bytesHeld = 0;        // GPU memory of the plugin's own targets
  int glObjectsHeld = 0;         // live GL objects owned by the plugin
  int slices = 1;                // lighting passes of the last frame
  double budgetScale = 1.0;      // the budget controller's quality scale (1 without a budget)
};

// The host's lighting pass, rendering into `target` from the host's single-sample G-buffer.
using LightingFunction = std::function<void(GLuintHandle target)>;

class Plugin {
 public:
  // Fails with InvalidConfig (a field the text parser would refuse: validateConfig), InvalidLayout,
  // UnsupportedContext (below GL 4.5), IncompleteFramebuffer (the driver refused a target built from
  // the layout's formats) or ShaderError (a built-in shader does not build, or lacks a uniform).
  // Features the context lacks make the plugin fall back, with a warning that says which and why:
  // no multisampling (GL_MAX_SAMPLES < 2) → every multi-sample method becomes `fxaa`; no stencil export →
  // slice counts in N passes; no timer queries → no pass times. Compute shaders are not used.
  static Result<std::unique_ptr<Plugin>> create(const Description& description);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  // The framebuffer the host's model pass renders into: the plugin's MSAA G-buffer for
  // multi-sample methods, the host's own otherwise.
  GLuintHandle geometryFramebuffer() const;
  // For `coverage`: a multisampled depth-only framebuffer the host draws its models into once more
  // (colour writes off), after the model pass. 0 when the method needs no such pass.
  GLuintHandle coverageFramebuffer() const;
  // After the model pass. Returns the first error of a pass (none are expected once create succeeded).
  Status resolve(const FrameInfo& frame);
  // Runs `lighting` once per slice and composites; for single-slice methods, once into the host's
  // light framebuffer. Errors: WrongCallOrder when a method with an MSAA G-buffer is shaded without
  // resolve() since the previous shade() (the host's G-buffer would hold nothing of this frame).
  Status shade(const LightingFunction& lighting);
  // After the host's tonemap, on the display target: the coverage filter, then FXAA (as configured).
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
  Stats stats() const;
  std::vector<std::string> warnings() const;  // every warning since creation, oldest first

 private:
  struct Impl;
  explicit Plugin(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace retroaa
