// The plain types of retroaa's API: how a host describes its G-buffer and frame, and what the plugin
// reports. plugin.h adds the Plugin class; the plugin's own sources use these without it.
#pragma once

#include "retroaa/config.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace retroaa {

using GLuintHandle = unsigned int;  // a GL object name; keeps <GL/gl.h> out of this header
using GLenumValue = unsigned int;

enum class AttachmentRole : uint8_t {
  Albedo,  // rgb albedo; averaged
  // Position with view depth in channel `depthChannel`, encoded per DepthEncoding (DepthSource::
  // PositionChannel); with another depth source, any position (world space too), averaged.
  ViewPosition,
  // The surface normal, encoded per GBufferLayout::normalEncoding (xyz, or octahedral in xy) in any one
  // space; averaged as decoded unit vectors and re-encoded; w gloss with NormalEncoding::Xyz (averaged apart).
  NormalGloss,
  Specular,  // averaged
  Emissive,  // averaged (the sky lives here for background pixels)
  Other,     // averaged
};

// How the host stores view depth in the position attachment (distance in front of the camera, m).
struct DepthEncoding {
  enum class Kind : uint8_t {
    Linear,        // stored = d
    LogAboveKnee,  // stored = d below `knee`, knee·(1 + log2(d/knee)) above it
    // FreeSpace Open's compressed view z (z-compress.sdr, since FSO PR #7245): stored =
    // compress_depth_value(-d), piecewise linear below 10 m and exponential in segments to 100, 1570,
    // 3000, 10 000, 100 000 m and `farDistance` (FSO's GLOBAL_FAR_Z); positive near, negative far.
    // Background is what FSO's resolve treats as background: decoded d ≤ 0.001 m (FSO clears to 0).
    FsoCompressedViewZ,
  };
  Kind kind = Kind::Linear;
  float knee = 8192.0f;              // metres (LogAboveKnee)
  float backgroundAbove = 65280.0f;  // stored values at or above this mark "no geometry" (Linear, LogAboveKnee)
  float farDistance = 1e10f;         // metres, FSO's GLOBAL_FAR_Z = Max_draw_distance (FsoCompressedViewZ; > 1e5)
};

// How the host maps its gloss channel (NormalGloss.w) to a specular exponent; retroaa's aggregates
// lower gloss by the spread of the normals they merge (Toksvig) in exponent space.
struct GlossEncoding {
  bool present = false;             // false: gloss is averaged like any channel
  float log2ExponentScale = 10.0f;  // exponent = exp2(gloss · scale + bias)
  float log2ExponentBias = 1.0f;
};

// How the host's depth buffer maps to view depth d, with FrameInfo's near and far planes (the methods
// with a prepass or a history, and every pass when the depth source is the depth buffer). The value at the far end
// (1, or 0 for the reversed kinds) marks "no geometry".
enum class DepthBufferEncoding : uint8_t {
  Perspective,  // a standard perspective projection's window depth, near 0, far 1 (FreeSpace Open)
  Logarithmic,  // log2(d / near) / log2(far / near), written by the model shader
  // Reversed-Z: near 1, far 0, with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): n(f − d) / (d(f − n)).
  ReversedPerspective,
  ReversedInfinite,  // reversed-Z with the far plane at infinity: n / d (FrameInfo::farPlane unused)
  // A perspective projection whose clip z runs 0 … w (Direct3D's convention: Irrlicht's
  // buildProjectionMatrixPerspectiveFovLH, SuperTuxKart's) under GL's default clip control and depth range:
  // window depth 0.5 + 0.5 × Perspective's, 0.5 at the near plane, 1 at the far.
  PerspectiveClipZeroToOne,
};

// Where the plugin reads each sample's view depth (closeness tests, edges, clustering, background).
enum class DepthSource : uint8_t {
  // Channel `depthChannel` of the ViewPosition attachment, per `depthEncoding`; background is a stored
  // value at or above `depthEncoding.backgroundAbove` (FSO's compressed z: decoded depth <= 0.001 m).
  PositionChannel,
  // The hardware depth buffer, per `depthBufferEncoding` and FrameInfo's planes; background is the far
  // value. No position attachment is needed; the slices write each sample's depth into the host's
  // depth texture as well, for a host whose lighting rebuilds positions from it.
  DepthBuffer,
  // The ViewPosition attachment's xyz is a world-space position: view depth is −(V·p).z with
  // FrameInfo::viewMatrix. Background is the depth buffer's far value (per `depthBufferEncoding`).
  WorldPosition,
};

// How the NormalGloss attachment holds the normal.
enum class NormalEncoding : uint8_t {
  Xyz,         // xyz as a vector (normalised or not); w gloss
  Octahedral,  // xy octahedral (Cigolle et al. 2014) in [-1, 1]; zw left to the host, averaged
  // xy Crytek's spheremap (Mittring, "A bit more deferred", 2009: normalize(n.xy)·sqrt(n.z/2 + 1/2)),
  // stored ×½ + ½ in [0, 1] as SuperTuxKart's unorm RGBA8 target holds it; zw left to the host, averaged
  Spheremap,
};

// The encoding of the values the host's display target holds after its tonemap.
enum class DisplayEncoding : uint8_t {
  DisplayEncoded,  // gamma-encoded for the screen (sRGB-like): what most tonemaps write into RGBA8
  Linear,          // linear light in an RGBA8 or float target (the window shows them as they are)
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
  DepthSource depthSource = DepthSource::PositionChannel;
  int depthChannel = 2;  // channel of ViewPosition holding encoded depth (DepthSource::PositionChannel)
  DepthEncoding depthEncoding;
  NormalEncoding normalEncoding = NormalEncoding::Xyz;
  // With NormalEncoding::Xyz: the normal is in view space, so z ≥ 0 for whatever the camera sees (FSO's).
  // A prepass that keeps normals then keeps x and y alone (RG16F, 4 B a sample) and rebuilds z; otherwise
  // (world space, or any other) it keeps the whole normal in the attachment's own format.
  bool normalsInViewSpace = false;
  // For a method with a history: the attachment (index into `attachments`, any role, a float format of two or more
  // channels) where the model pass writes each pixel's screen motion since the previous frame: xy =
  // this frame's position − the previous frame's, in pixels, both without jitter, camera and object
  // motion together. Its geometry pixels then fetch their history there, so objects that move on their
  // own keep theirs; background pixels reproject by the camera. -1: none, the camera alone.
  int velocityAttachment = -1;
  GlossEncoding glossEncoding;
  DepthBufferEncoding depthBufferEncoding = DepthBufferEncoding::Perspective;
  GLuintHandle gbufferFramebuffer = 0;   // the host's single-sample G-buffer (attachments + depth)
  GLuintHandle depthStencilTexture = 0;  // any depth or depth-stencil texture format
  // Instead of depthStencilTexture, a single-sample depth(-stencil) renderbuffer: the plugin mirrors it in
  // a texture of its own (+ its size), copied back after resolve() and in before post() where needed.
  GLuintHandle depthStencilRenderbuffer = 0;
  // The host's lighting rebuilds positions from depthStencilTexture: each slice then writes its samples'
  // depth there too, as it writes their attributes into the attachments. Implied by DepthSource::DepthBuffer.
  bool lightingReadsDepth = false;
  uint8_t hostStencilBits = 0x00;  // stencil bits the host owns; retroaa leaves them alone
  // Where the host's lighting accumulates (0: the default framebuffer, the window), and its colour
  // texture: any colour format, e.g. an RGBA16F HDR target, or the host's sRGB display when it lights
  // straight into it. Slices composite into a float texture directly; without a texture (0), or with 8 bits
  // per channel, they sum in a half-float target of the plugin's and draw it into lightFramebuffer once.
  GLuintHandle lightFramebuffer = 0, lightTexture = 0;
  // lightFramebuffer's further colour attachments, draw buffers 1, 2, … in order, for a host whose
  // lighting writes several outputs (SuperTuxKart: diffuse at 0, specular at 1). Each is lit and
  // composited as lightTexture is; each must hold floats (e.g. R11F_G11F_B10F), and lightTexture too.
  std::vector<GLuintHandle> extraLightTextures;
  // Where the host composes scene colour after lighting, for a host whose shade() callback covers more than
  // lighting (a material combine multiplying light by albedo, a sky or background drawn where depth is far,
  // fog): its colour target and texture, e.g. SuperTuxKart's FBO_COLORS / RTT_COLOR. 0 (the default): the
  // callback produces light, and the plugin composites light. Named: the callback produces composed colour
  // (shade(ComposingFunction)); a slice method composites that per slice into composedTexture, and the light
  // textures above become the callback's scratch, lit per slice (after shade() they hold no defined frame).
  // Each slice then presents to every pass of the callback its own samples: their attributes in the G-buffer,
  // their depth in the targets' depth buffer (a far-plane sky test sees the slice's surface) and, where the
  // lighting reads depth, in the host's depth texture. composedTexture must hold floats or RGBA8.
  GLuintHandle composedFramebuffer = 0, composedTexture = 0;
  // The host draws forward passes after shade() (transparents, particles, gizmos) between Plugin::beginForward()
  // and endForward() each frame. With a multisampled G-buffer the plugin then holds a multisampled copy of the
  // scene colour (RGBA16F, `samples` per pixel) for them to draw into, and shade() keeps each lit sample's own
  // colour there. false: beginForward() hands back the host's own scene colour framebuffer.
  bool drawsForwardPasses = false;
  // The tonemapped display that post() filters (RGBA8 or GL_SRGB8_ALPHA8); needed only by the methods
  // whose MethodInfo::filtersDisplay says so and by every stacked +filter (0 elsewhere: a config that
  // needs it without one is refused with InvalidLayout naming the method).
  GLuintHandle displayFramebuffer = 0, displayTexture = 0;
  // What the display's stored values are (an sRGB-format display is always DisplayEncoded: the format
  // says so). Every post pass that mixes colours (smaa, coverage, reconstruct, temporal after tonemapping)
  // decodes DisplayEncoded values to linear light first and mixes Linear values as stored; every one that
  // thresholds contrast (smaa's and fxaa's edges) sees Linear values sRGB-encoded.
  DisplayEncoding displayEncoding = DisplayEncoding::DisplayEncoded;
};

enum class LogLevel : uint8_t { Info, Warning, Error };
using LogCallback = std::function<void(LogLevel, const std::string&)>;

// Context features the plugin uses when present. Masking one off makes the plugin behave as on a
// context without it (for testing fallbacks, or to work around a driver bug).
enum Feature : uint32_t {
  kFeatureStencilExport = 1u << 0,       // ARB_shader_stencil_export: slice counts in one pass (else ⌈log2(N+1)⌉)
  kFeatureTimerQuery = 1u << 1,          // GL_TIME_ELAPSED: per-pass GPU times (else none reported)
  kFeaturePipelineStatistics = 1u << 2,  // ARB_pipeline_statistics_query: per-pass shader invocations (else 0)
};

struct Description {
  Config config;
  GBufferLayout layout;
  LogCallback log;                // receives every warning (clamps, fallbacks); may be empty
  uint32_t disabledFeatures = 0;  // Feature bits to treat as missing
  int maxSamplesLimit = 0;        // treat GL_MAX_SAMPLES as at most this (0: the context's own; 1: no MSAA)
  // The most GPU memory the multisampled (or supersampled) G-buffer may take: a config or size asking for more
  // is refused (InvalidConfig, naming both) before anything is allocated. 0: no budget (the driver decides).
  uint64_t gbufferBudgetBytes = uint64_t(8) << 30;
};

// For a method with a history, in place of a velocity attachment: an object that moves on its own (a kart, a
// door), as a box around it in this frame and the last. The plugin reprojects each pixel whose surface lies
// inside the box (depth and the view say where) with the object's motion, so the history follows the object;
// no shader of the host's changes. Boxes may be loose: a surface inside one that does not move with the
// object (the road under a kart) is reprojected with it, and the history's depth test rejects it.
struct MovingObject {
  // This frame's transform of the cube [-1, 1]³ onto the object's box, in the space viewMatrix maps from,
  // column-major; and the same transform a frame ago.
  float boxToWorld[16] = {};
  float previousBoxToWorld[16] = {};
};
constexpr int kMaxMovingObjects = 16;  // more in one frame: the nearest are kept (with one warning)

// Per-frame camera facts for the closeness tests.
struct FrameInfo {
  // The projection's vertical field of view (what FreeSpace Open passes its MSAA resolve as `fov`).
  // Eq. 1's pixel footprint uses the horizontal one, derived from this and the layout's aspect ratio.
  float verticalFovRadians = 1.0f;
  float nearPlane = 0.1f, farPlane = 1e6f;  // metres, for DepthBufferEncoding (and DepthSource::DepthBuffer)
  // World to view, column-major as GL and GLM store it (DepthSource::WorldPosition, and a history).
  float viewMatrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  // For a method with a history: the frame's perspective projection without the jitter, column-major (view to clip, GL
  // conventions; reversed-Z and infinite far planes included). The plugin keeps the previous frame's
  // view and projection itself and reprojects with them. All zero (the default): not given, and
  // no history is kept (with one warning).
  float projectionMatrix[16] = {};
  // For a method with a history: the view does not continue the previous frame's (a cut, a teleport, a new level): the
  // history is dropped and this frame starts a new one.
  bool cameraCut = false;
  // For a method with a history: the objects that move on their own this frame (MovingObject), at most
  // kMaxMovingObjects; the rest of the frame reprojects with the camera (or the velocity attachment).
  std::vector<MovingObject> movingObjects = {};
};

// For a method with a history: the sub-pixel offset, in pixels (x right, y up), by which the host shifts this frame's
// projection (Plugin::jitter).
struct Jitter {
  float x = 0, y = 0;
};

// What the host sets around a kind of model draw (Plugin::cutOutDrawSettings).
struct DrawSettings {
  float sampleShading = 0;   // enable GL_SAMPLE_SHADING with glMinSampleShading(it) where above 0
  float textureLodBias = 0;  // added to the material samplers' mip bias
};

// One plugin pass of a measured frame (Config::measureGpuTime).
struct PassStats {
  std::string name;                  // e.g. "resolve", "lighting"
  double ms = 0;                     // GPU time (GL_TIME_ELAPSED); 0 without timer queries
  uint64_t fragmentInvocations = 0;  // fragment-shader invocations (pipeline statistics; 0 without them)
  uint64_t computeInvocations = 0;   // compute-shader invocations (the same)
  // The least memory traffic the pass's job needs (formats × samples × pixels read and written), where
  // it is fixed: divided by the machine's copy bandwidth, the time no implementation can beat. 0: not
  // stated (the traffic depends on the frame).
  uint64_t minimumBytes = 0;
  // Where the pass cannot be measured (a floor the device cannot reproduce: measure_pass_floors), why;
  // its figures are then 0 and mean nothing.
  std::string unmeasured;
};

struct Stats {
  Method method = Method::Off;
  int samples = 1;      // samples granted (after clamping)
  uint64_t pixels = 0;  // width × height
  // The GPU's figures, read without waiting: they describe frame `measuredFrame`, usually a frame or
  // two behind `framesStarted` (Plugin::waitForStats() waits for the last one). 0: no frame is back
  // since the last reconfigure() or resize().
  uint64_t framesStarted = 0;  // frames begun (resolve() or shade()) since creation
  uint64_t measuredFrame = 0;
  uint64_t lightingEvaluations = 0;  // pixels lit, summed over the lighting calls of the measured frame
  // The same per lighting call, in order: one per slice (slice 0 lights every pixel; a later slice, the
  // pixels whose count reaches it), beside each slice's pass times (PassStats in the same order).
  std::vector<uint64_t> lightingEvaluationsBySlice;
  double evaluationsPerPixel() const { return pixels ? double(lightingEvaluations) / pixels : 0; }
  std::vector<PassStats> passes;  // plugin passes of the measured frame (measureGpuTime)
  uint64_t bytesHeld = 0;         // GPU memory of the plugin's own targets
  int glObjectsHeld = 0;          // live GL objects owned by the plugin, but for the statistics' queries:
  int statisticsQueriesHeld = 0;  // the query ring (bounded; freed by reconfigure() and resize())
  int slices = 1;                 // lighting passes of the last frame begun
  double budgetScale = 1.0;       // the budget controller's quality scale (1 without a budget)
};

// The host's lighting pass, rendering into `target` from the host's single-sample G-buffer.
using LightingFunction = std::function<void(GLuintHandle target)>;

// What a composing callback draws into, once per slice (GBufferLayout::composedFramebuffer): its lighting into
// `light` (the layout's light textures as draw buffers 0, 1, …), then its combine, sky and fog into
// `composed` (one colour attachment). Both carry this slice's depth (far where a sample has no geometry) with
// the plugin's slice mask in stencil, the stencil test set: a pass that keeps the stencil test on (and may
// enable the depth test, e.g. GL_LEQUAL for a sky at the far plane) runs on this slice's pixels only. For a
// single-slice method they are the layout's own lightFramebuffer and composedFramebuffer.
struct ShadeTargets {
  GLuintHandle light = 0;
  GLuintHandle composed = 0;
};
using ComposingFunction = std::function<void(const ShadeTargets& targets)>;

}  // namespace retroaa
