// The pieces every technique shares, which the plugin owns: the MSAA G-buffer, the resolve into the
// host's G-buffer, the slice mechanism and the post target. The techniques themselves (technique.h)
// live one per file beside this one, each with one folder of shaders/.
#pragma once

#include "../context.h"

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace retroaa {

// The multisampled mirror of the host's G-buffer: same attachments and formats, N samples, plus a
// multisampled depth-stencil. The host's model pass renders into it unchanged. N = 1 allocates plain
// single-sample textures (a "multisample" texture of one sample may rasterise at a corner sample
// position, or be backed by more samples), so the resolve at N = 1 sees exactly what `off` sees.
// The uniforms MsaaGBuffer::beginPass sets, for the uniform list of a program that reads the G-buffer.
#define RETROAA_GBUFFER_PASS_UNIFORMS RETROAA_DEPTH_ENCODING_UNIFORMS, "uFootprintTan"
// The uniform a slice writer's depth variant declares (common/gbuffer.glsl, WRITE_DEPTH).
#define RETROAA_SLICE_DEPTH_UNIFORMS "uMinCount"

// The cell centres of an m×m grid over the pixel, x and y per cell in [0, 1)², cell s = m·row + column:
// a supersampled G-buffer's sub-positions.
std::vector<float> orderedGridPositions(int m);
// The index of the layout's first attachment with `role`; -1 where it has none.
int findRole(const GBufferLayout& layout, AttachmentRole role);
// The #defines common/depth.glsl, depth_buffer.glsl and normal.glsl need for the layout's depth source and
// encodings (DEPTH_SOURCE, DEPTH_CHANNEL, DEPTH_ENCODING, DEPTH_BUFFER_ENCODING, NORMAL_ENCODING).
std::string depthEncodingDefines(const GBufferLayout& layout);

class MsaaGBuffer {
 public:
  // `supersample` = m ≥ 2: an m·W × m·H single-sample G-buffer instead, m² sub-positions per pixel.
  static Result<std::unique_ptr<MsaaGBuffer>> create(PluginContext& context, int samples, int supersample = 0);
  GLuint framebuffer() const { return framebuffer_.get(); }
  GLuint attachment(size_t i) const { return attachments_[i].get(); }
  GLuint depthStencil() const { return depthStencil_.get(); }
  int samples() const { return samples_; }  // as allocated by the driver (may exceed the request)
  int requestedSamples() const { return requested_; }
  int supersample() const { return supersample_; }  // m, or 1 for a multisampled G-buffer
  bool multisampled() const { return samples_ > 1 || multisampledStorage_; }
  // Multisampled, not supersampled: the model pass rasterises several samples per pixel into it.
  bool rasterisesPerSample() const { return multisampled() && supersample_ == 1; }
  // The driver's sample positions, x and y per allocated sample in [0, 1)²; the centre for single-sample
  // storage. Binds the G-buffer's framebuffer.
  std::vector<float> samplePositions() const;
  // The #defines shaders reading this G-buffer need (shaders/common/gbuffer.glsl): sample count,
  // attachment roles, depth encoding, and one output per host attachment with STORE_OUTPUTS(values).
  std::string shaderDefines(const GBufferLayout& layout, bool withOutputs = true) const;
  // Binds attachment i to texture unit i and the depth-stencil to kUnitDepthStencil.
  void bind(const GBufferLayout& layout) const;
  // A full-screen pass reading this G-buffer: uses `program`, binds the G-buffer and sets the uniforms
  // every such program declares (RETROAA_GBUFFER_PASS_UNIFORMS: depth encoding, Eq. 1's footprint).
  void beginPass(const ShaderProgram& program, const PluginContext& context, const FrameInfo& frame) const;
  uint64_t bytes() const { return bytes_; }

 private:
  std::vector<GlTexture> attachments_;
  GlTexture depthStencil_;
  GlFramebuffer framebuffer_;
  int samples_ = 1;
  int requested_ = 1;
  int supersample_ = 1;
  bool multisampledStorage_ = false;
  uint64_t bytes_ = 0;
};

// `resolve`: the depth-aware resolve of Magnussen (and FreeSpace Open's variant) from the MSAA
// G-buffer into the host's single-sample G-buffer and depth.
class SliceRenderer;
// Slice counts the resolve writes from the samples it has fetched anyway: `edge`'s detector
// (shaders/edge/detector.glsl) into `counts` (R8UI), N where the pixel's samples see more than one
// surface, else 1. Saves the edge mask a pass that reads every sample again.
struct ResolveCounts {
  EdgeDetector detector = EdgeDetector::Coverage;
  float depthCloseness = 0, normalCosine = 0;  // the depth and normal detectors' thresholds
  GLuint counts = 0;
};

class ResolvePass {
 public:
  static Result<std::unique_ptr<ResolvePass>> create(PluginContext& context, const MsaaGBuffer& source);
  // With `counts` (and the full-screen resolve: the compute one does not count), the counts as well
  // (wroteCounts() says whether this frame's did).
  // `keepDepthForRestore`: the depth as written also into floats, which restore() writes back where the
  // host's depth holds stencil bits (see keepForRestore).
  Status run(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame,
             const ResolveCounts* counts = nullptr, bool keepDepthForRestore = false);
  bool wroteCounts() const { return wroteCounts_; }
  // The same resolve into the host's attachments only (its depth holds the resolved depth already),
  // where `slices` overwrote them: after the slices, so that the host's G-buffer holds the resolved
  // surface again (from keepForRestore's copies where it took them; else the whole resolve again).
  Status restore(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame,
                 const SliceRenderer& slices);
  // Before the slices overwrite the host's attachments: a copy of them (and of its depth where the slices
  // write it), which restore() then writes back: copies instead of a second resolve, and whatever the host
  // drew into its G-buffer since resolve() is kept too. A depth with stencil bits cannot be copied back
  // without undoing the host's stencil: restore() writes the resolve's own depth floats back through
  // gl_FragDepth instead (run()'s keepDepthForRestore; a depth read back from the buffer as floats and
  // written again can come back one unit off on llvmpipe, these come back as the resolve stored them).
  void keepForRestore(PluginContext& context, const SliceRenderer& slices);
  // Whether run() must keep its depth floats for a restore after `slices`.
  static bool restoreNeedsDepthFloats(const PluginContext& context, const SliceRenderer& slices);
  bool computeRequested() const { return computeRequested_; }  // resolve_compute as created
  ResolveWeighting weighting() const { return weighting_; }  // resolve_weighting as created: a constant of its programs
  // Frees what one config's slices asked of the resolve (its counting programs and target, the restore's
  // kept copies): a new config asks again, so what it holds follows it, not the configs before it.
  void releaseForNewConfig() {
    countingPrograms_.clear();
    countingTarget_ = GlFramebuffer();
    countingTargetCounts_ = 0;
    kept_.clear();
    keepingProgram_ = ShaderProgram();
    for (ShaderProgram& writer : keptWriters_) writer = ShaderProgram();
    keepingTarget_ = GlFramebuffer();
    if (!computes()) {
      resolvedDepth_ = GlTexture();
      bytes_ -= depthFloatBytes_;
      depthFloatBytes_ = 0;
    }
    bytes_ -= keptBytes_;
    keptBytes_ = 0;
    keptThisFrame_ = keptDepth_ = depthFloatsWritten_ = false;
  }
  bool computes() const { return computeProgram_.get() != 0; }  // … and the layout allowed it
  uint64_t bytes() const { return bytes_; }

 private:
  static constexpr int kTileSize = 8;  // resolve.comp's work group: 8 × 8 pixels
  // What every resolve program is built with: the layout's defines and the weighting it was created for.
  std::string defines(const PluginContext& context, const MsaaGBuffer& source, bool withOutputs = true) const;
  // resolve_compute: resolve.comp and what carries its depth into the host's (none where the layout's
  // formats or the context's image units do not allow it, with a warning).
  Status createCompute(PluginContext& context, const MsaaGBuffer& source);
  // The layout check: on the first frame, occlusion queries count the pixels without geometry and those
  // with geometry at view depth <= 0; a later frame reads them once available (never waiting) and warns,
  // naming the layout fields, when the data looks unlike the layout's description.
  void checkLayout(PluginContext& context, const MsaaGBuffer& source);
  // The counting resolve's program for a detector (built when first asked) and its target: the host's
  // attachments, the counts after them, the host's depth.
  Result<const ShaderProgram*> countingProgram(PluginContext& context, const MsaaGBuffer& source, EdgeDetector detector,
                                               bool keepDepth);
  Result<GLuint> countingTarget(PluginContext& context, GLuint counts, bool keepDepth);
  // The full-screen resolve that also writes its depth floats, and its target (built when first asked).
  Result<GLuint> keepingTarget(PluginContext& context, const MsaaGBuffer& source);
  // depthTarget_ and writeDepthProgram_, once: write_depth.frag into the host's depth alone.
  Status createDepthWriter(PluginContext& context);
  // resolvedDepth_ for the full-screen resolve, once (its bytes in depthFloatBytes_).
  void createDepthFloats(PluginContext& context);
  // resolvedDepth_ into the host's depth alone (write_depth.frag; the stencil test off).
  void writeResolvedDepth(PluginContext& context) const;
  // restore_kept.frag (built when first asked): kept_'s attachments back into the host's, and with
  // `depthFloats` resolvedDepth_ into its depth, in one draw.
  Result<const ShaderProgram*> keptWriter(PluginContext& context, const MsaaGBuffer& source, bool depthFloats);
  std::vector<GlTexture> kept_;  // keepForRestore()'s copies: each attachment, then the depth where kept
  bool keptThisFrame_ = false, keptDepth_ = false;
  bool depthFloatsWritten_ = false;  // this frame's run() wrote resolvedDepth_
  uint64_t depthFloatBytes_ = 0;     // the full-screen resolve's resolvedDepth_, in bytes_
  ShaderProgram keepingProgram_;
  ShaderProgram keptWriters_[2];  // keptWriter()'s, without and with the depth floats
  GlFramebuffer keepingTarget_;
  uint64_t keptBytes_ = 0;  // their share of bytes_
  ShaderProgram program_, restoreProgram_, layoutCheck_;
  GlFramebuffer hostTarget_;  // the host's attachments + depth, without its stencil bits
  std::map<std::pair<EdgeDetector, bool>, ShaderProgram> countingPrograms_;  // by detector, keeping the depth
  GlFramebuffer countingTarget_;
  GLuint countingTargetCounts_ = 0;  // the counts texture countingTarget_ holds
  bool countingTargetKeepsDepth_ = false;
  bool wroteCounts_ = false;
  ShaderProgram computeProgram_, writeDepthProgram_;
  GlTexture resolvedDepth_;    // R32F: the resolve's depth as written (compute, or keepDepthForRestore)
  GlFramebuffer depthTarget_;  // the host's depth alone
  bool computeRequested_ = false;
  ResolveWeighting weighting_ = ResolveWeighting::Median;
  uint64_t bytes_ = 0;
  GlQuery noGeometryQuery_, nonPositiveQuery_;
  enum class LayoutCheck : uint8_t { ToIssue, Pending, Done } layoutCheckState_ = LayoutCheck::ToIssue;
};

// The slice mechanism (DESIGN.md), shared by every multi-slice method: a per-pixel slice count in a
// stencil mask, then per slice s: sample s written into the host's G-buffer where count > s, the
// host's unchanged lighting run under the stencil test into a plugin target, and weight × light
// composited into the host's light target (weight = 1 / count). Never touches the host's stencil.
class ForwardTarget;
class SliceRenderer {
 public:
  static Result<std::unique_ptr<SliceRenderer>> create(PluginContext& context, const MsaaGBuffer& source);
  // Runs `maskProgram` (a full-screen shader writing the count to location 0, and to
  // gl_FragStencilRefARB when `stencilExport`) to fill the counts and the stencil mask.
  // `target` (0: the plugin's own) must hold the counts at location 0 and this renderer's mask as stencil.
  Status writeMask(PluginContext& context, GLuint maskProgram, bool stencilExport, GLuint target = 0);
  // The stencil mask from counts already written (ResolvePass::run's): one pass reading a byte a pixel.
  Status writeStencilFromCounts(PluginContext& context);
  // Every pixel's count `count` (per-sample: every sample lit): two clears, no pass.
  void writeUniformMask(PluginContext& context, int count);
  GLuint counts() const { return counts_.get(); }
  // Whether each slice writes the host's depth texture too (DepthSource::DepthBuffer: the host's
  // lighting rebuilds positions from it).
  bool writesHostDepth() const { return depthWriter_.get() != 0; }
  // Whether each slice's depth stays in the targets the host's callback draws into (the layout composes:
  // a far-plane sky or a depth-tested fog must see the slice's surface).
  bool keepsSliceDepth() const { return maskDepthWriter_.get() != 0; }
  // The #defines of a slice writer: its G-buffer write (`hostDepth` false), which also writes the slice's
  // depth into the mask where the slices keep it, or its variant for the host's depth texture alone
  // (`hostDepth`; needed where writesHostDepth()).
  std::string writerDefines(const MsaaGBuffer& source, const GBufferLayout& layout, bool hostDepth) const {
    if (hostDepth) return "#define WRITE_DEPTH 1\n" + source.shaderDefines(layout, false);
    return (keepsSliceDepth() ? "#define WRITE_DEPTH 1\n" : "") + source.shaderDefines(layout);
  }
  GLuint mask() const { return mask_.get(); }
  // How a method uses the slices.
  struct Plan {
    std::vector<int> sampleOrder;  // slice s lights sample sampleOrder[s] (identity when empty)
    // false: slice 0 writes sample 0 only where count > 1 (single-count pixels keep the resolved
    // G-buffer); true: slice 0 writes sampleOrder[0] everywhere.
    bool firstSliceEverywhere = false;
    // Runs after slice 0 is lit, before anything is composited: a method that needs the lit first
    // sample to choose its counts writes the mask here (writeMask). Empty: the mask is already there.
    std::function<Status()> maskAfterFirstSlice;
    int sliceCount = 0;  // most slices a pixel may need (0: the sample count)
    // A technique's own slice writer (null: sample sampleOrder[s] verbatim). It is given uniform
    // `uSlice` and the G-buffer; `bindWriteInputs` binds and sets on the program what else it reads.
    // Both are built with writerDefines(): `writeProgram` with hostDepth false, and where the slices write
    // the host's depth (writesHostDepth()) `writeDepthProgram` with it true: it writes gl_FragDepth for the
    // pixels of the slice.
    const ShaderProgram* writeProgram = nullptr;
    const ShaderProgram* writeDepthProgram = nullptr;
    std::function<void(const ShaderProgram&)> bindWriteInputs;
    // A technique's own composite weights (null: 1 / count). It is given uniform `uSlice` and the slice's
    // light as sampler `uSliceLight` (listed when it is built); `bindCompositeInputs` binds the rest.
    const ShaderProgram* compositeProgram = nullptr;
    std::function<void()> bindCompositeInputs;
    // Runs on each slice's light before it is composited (SMAA S2x filters it): given the slice and its
    // light texture, returns the texture to composite instead. Empty: the light as lit.
    std::function<Result<GLuint>(int slice, GLuint light)> filterSliceLight;
  };
  // Lights every slice through `lighting` and composites (weight 1 / count). Counts evaluations with an
  // occlusion query on each slice's write (a sample whose write discards, being non-finite, counts as
  // not lit).
  // With a composing layout, `compose` lights into the host's light textures and composes into the plugin's
  // per-slice colour, which is composited into the layout's composedTexture instead.
  // With a forward target, each slice's colour is kept in the sample it lit (plans that light one sample a slice
  // with the stock writer; the pixel's colour fills the rest at Plugin::beginForward()).
  Status shade(PluginContext& context, const MsaaGBuffer& source, const ComposingFunction& compose, const Plan& plan,
               const ForwardTarget* forward);
  std::vector<uint8_t> readCounts() const;
  // Where the pixels with a count of at least `minCount` lie: the tiles that hold one, once shade() has
  // listed this frame's (counts that vary over the frame); the whole screen otherwise, or for
  // `minCount` <= 1. A pass limited to those pixels (by the stencil, or by discarding) draws these.
  TileDraw tilesWhereCountAtLeast(int minCount) const;
  // The same pixels as the stencil test over this renderer's mask (none where `minCount` <= 1), and the
  // tiles that hold them: what a pass drawn over the mask passes to drawTiles.
  TileDraw limitToCountAtLeast(int minCount) const;
  GLuint firstSliceLight() const { return light_.get(); }  // slice 0's light, inside maskAfterFirstSlice
  // What the last shade() overwrote in the host's G-buffer: every pixel, or those with count > 1; and the
  // framebuffer of the host's attachments over the count stencil.
  bool lastWriteEverywhere() const { return lastWriteEverywhere_; }
  GLuint writer() const { return sliceWriter_.get(); }
  uint64_t bytes() const { return bytes_; }

 private:
  // shade()'s steps for one slice: write its samples into the host's G-buffer (returns the occlusion
  // query counting its pixels; 0 for slice 0), run the host's lighting, composite its weighted light;
  // then, once every slice is in, the half-float sum into the host's light target.
  Status createTargets(PluginContext& context);  // create()'s framebuffers (and the half-float sum's pass)
  Status createPrograms(PluginContext& context, const MsaaGBuffer& source);
  // Binds `target` (counts at location 0, the mask as depth-stencil) and clears the counts and the stencil
  // to `count`, the mask's depth to the far plane.
  void clearMask(PluginContext& context, GLuint target, int count);
  // The counts texture's values into the stencil, with colour writes off: through stencil export where
  // the context has it, else a bit at a time.
  void stencilFromCounts(PluginContext& context);
  GLuint writeSlice(PluginContext& context, const MsaaGBuffer& source, const Plan& plan, int slice);
  void lightSlice(PluginContext& context, const ComposingFunction& compose, int slice);
  void copyResolvedDepthIntoMask(PluginContext& context);  // a composing layout's depth for slice 0
  Status compositeSlice(PluginContext& context, const Plan& plan, int slice);
  void presentAccumulation(PluginContext& context);
  // The tile lists of this frame's counts (list_tiles.comp), for tilesWhereCountAtLeast().
  Status createTileLists(PluginContext& context);
  void listTiles(PluginContext& context);

  static constexpr int kTileSize = 16;  // pixels across a tile of list_tiles.comp
  static constexpr int kTileGroup = 8;  // tiles across its work group
  GlTexture light_, mask_, counts_;
  // lightTarget_: where the callback lights (the plugin's light_ and extraLight_; with a composing layout the
  // host's own light textures); composeTarget_: where a composing callback composes (light_), else none.
  GlFramebuffer maskTarget_, lightTarget_, composeTarget_, sliceWriter_, compositeTarget_;
  // The layout's extraLightTextures: each slice's light for them (lightTarget_'s attachments 1, 2, …)
  // and a composite target onto each host texture.
  std::vector<GlTexture> extraLight_;
  std::vector<GlFramebuffer> extraCompositeTarget_;
  GlFramebuffer depthWriter_;      // the host's depth texture alone (DepthSource::DepthBuffer), else none
  GlFramebuffer maskDepthWriter_;  // the mask's depth alone (a composing layout), else none
  ShaderProgram copyDepth_;        // the host's resolved depth into the mask's (a composing layout)
  // Where the host's light texture has 8 bits per channel, or there is none: the slices' half-float sum
  // and its copy into the host's light target.
  GlTexture accumulation_;
  GlFramebuffer presentTarget_;
  ShaderProgram writeSlice_, writeSliceDepth_, composite_, markPixels_, presentLight_;
  ShaderProgram stencilFromCounts_;  // with stencil export: the counts into the stencil in one pass
  int maxCount_ = 1;
  // The tile lists: maxCount_ - 1 indirect draws over tileRectangles_ (list t - 1: tiles with a count above
  // t), reset from tileCommandsReset_ each frame they are listed; each tile's largest count in tileMaxima_.
  GlBuffer tileCommands_, tileCommandsReset_, tileRectangles_;
  GlTexture tileMaxima_;
  int tilesAcross_ = 0, tilesDown_ = 0;
  GLsizeiptr tileCommandBytes_ = 0;
  GlVertexArray tileArray_;
  ShaderProgram listTiles_;
  bool countsVary_ = false;   // the mask was written per pixel (writeMask, writeStencilFromCounts)
  bool tilesListed_ = false;  // this frame's tile lists are in tileCommands_ and tileRectangles_
  bool lastWriteEverywhere_ = true;
  uint64_t bytes_ = 0;
};

// The order that spreads the first k of N samples over the pixel for every k: the sample nearest the
// centre first, then each time the one farthest from those already taken. `positions` in [0, 1)².
std::vector<int> spreadingSampleOrder(const std::vector<float>& positionsXY);
// Holländer et al.'s order over a supersampled pixel's m×m window (sub-position s = m·row + column): the
// Bayer index matrices for m = 2 ([0 2; 3 1]) and m = 4 ([0 8 2 10; 12 4 14 6; 3 11 1 9; 15 7 13 5]),
// entry v naming the v-th sub-position taken; for m = 3 (no Bayer matrix) the spreading order of the
// grid's cell centres: the centre, then each time the cell farthest from those taken.
std::vector<int> bayerSampleOrder(int m);
// The order a G-buffer's samples are lit in: Bayer's for a supersampled one, the spreading order of the
// driver's sample positions for a multisampled one.
std::vector<int> sampleOrder(const MsaaGBuffer& source);

// Where the host's forward passes (transparents, particles, gizmos) draw after shade() when the method has a
// multisampled G-buffer: a multisampled colour target in the scene colour's place, each sample filled with its
// pixel's scene colour, over the G-buffer's own multisampled depth, so forward geometry is anti-aliased and
// depth-tested per sample against the opaque surfaces; its samples' mean goes back into the scene colour.
// Allocated with the G-buffer where the layout says the host draws forward passes.
class ForwardTarget {
 public:
  static Result<std::unique_ptr<ForwardTarget>> create(PluginContext& context, const MsaaGBuffer& source);
  GLuint framebuffer() const { return framebuffer_.get(); }
  void beginFrame(const PluginContext& context) const;  // at shade(): no sample kept yet
  // During the slices: the colour of the slice that lit `sample` where the pixel's count is at least minCount
  // (drawn over `tiles`, which hold those pixels).
  void keepSample(PluginContext& context, GLuint sliceColour, GLuint counts, int minCount, int sample,
                  const TileDraw& tiles) const;
  void keepShadedColour(const GBufferLayout& layout) const;  // at shade()'s end: the scene colour it composed
  // What the host drew into the scene colour since shade() into every sample kept, then the pixel's scene
  // colour into every sample not kept.
  void fill(PluginContext& context) const;
  void resolve(PluginContext& context) const;  // each pixel's mean into the scene colour
  uint64_t bytes() const { return bytes_; }

 private:
  GlTexture colour_, shadedColour_;
  GlFramebuffer framebuffer_, sceneColour_;
  ShaderProgram fill_, carry_, keep_, resolve_;
  mutable bool shadedColourKept_ = false;  // this frame's slices kept samples and the colour they composed
  uint64_t bytes_ = 0;
};

// What the host's forward passes drew this frame, for the post passes that rebuild a pixel from its
// neighbours' colours (`reconstruct`, `coverage`): they know the opaque surfaces' depth and normals, not a
// transparent's or a particle's, and would spread its colour into pixels it never touched. beginForward()
// keeps the scene colour as shade() left it; endForward() marks each pixel the forward passes changed. Any
// host's forward passes, whatever their state: nothing of theirs needs to cooperate. Held while the layout
// draws forward passes and an active technique readsForwardMask().
class ForwardMask {
 public:
  static bool appliesTo(const GBufferLayout& layout) {
    return layout.drawsForwardPasses && sceneColourTexture(layout) != 0;
  }
  static Result<std::unique_ptr<ForwardMask>> create(PluginContext& context);
  void clear() const;                                       // at shade(): nothing drawn this frame yet
  void keepSceneColour(const GBufferLayout& layout) const;  // at beginForward()
  void markChanges(PluginContext& context) const;           // at endForward(), the forward colour in the scene colour
  GLuint drawn() const { return drawn_.get(); }  // R8: 0 untouched, 0.5 under a film, 1 an edge of what was drawn
  uint64_t bytes() const { return bytes_; }

 private:
  GlTexture before_, drawn_;
  GlFramebuffer framebuffer_;
  ShaderProgram mark_;
  uint64_t bytes_ = 0;
};

// A pass that rewrites, in place, only the pixels a cheap test picks (FXAA's contrast test, reconstruct's
// sub-samples off their pixel's surface), in two draws: `mark` runs the test on every pixel and discards
// the pixels it leaves alone, the rest being marked in a stencil of its own; `rewrite` runs on the marked
// pixels alone and writes them into `output`. One draw with an early return would cost every pixel the
// costly part: llvmpipe runs both sides of a branch under a mask, and a stencil test drops whole blocks
// before the shader runs (SMAA's reference marks its edges for its searches the same way).
class MarkedRewrite {
 public:
  // `output`: a single-sample texture of the layout's size, which neither program reads.
  static Result<MarkedRewrite> create(PluginContext& context, GLuint output, const std::string& label, uint64_t& bytes);
  // `bind(program)` uses the program and binds its inputs; it is called before each draw.
  void run(const PluginContext& context, const ShaderProgram& mark, const ShaderProgram& rewrite,
           const std::function<void(const ShaderProgram&)>& bind) const;

 private:
  GlTexture marked_;  // stencil: 1 where `mark` kept the pixel
  GlFramebuffer markTarget_, rewriteTarget_;
};

// Where the post passes (MethodInfo::filtersDisplay) render: a plugin-owned copy of the host's display
// target in its format, copied back after each pass, and the bilinear sampler they read the display
// with. The passes work on the display's stored (gamma-encoded) values: an sRGB-format display
// (GL_SRGB8_ALPHA8), whose reads would decode to linear and whose writes would encode again, is copied
// byte for byte into an RGBA8 stand-in for the passes (begin) and back when they are done (end).
class PostTarget {
 public:
  static Result<std::unique_ptr<PostTarget>> create(PluginContext& context);
  void begin(const GBufferLayout& layout) const;  // before the first post pass of a frame
  void end(const GBufferLayout& layout) const;    // after the last
  GLuint input(const GBufferLayout& layout) const { return encodedCopy_ ? encodedCopy_.get() : layout.displayTexture; }
  void bindAsOutput(const PluginContext& context) const;  // framebuffer, viewport, plain state
  // `texture` (input() or copyOfInput()), bilinear, as `program`'s `sampler`.
  void bindBilinear(const ShaderProgram& program, const char* sampler, GLuint texture) const;
  void copyBack(const GBufferLayout& layout) const;  // the output into input()
  // A pass that rewrites only some pixels (MarkedRewrite, a compute pass) writes input() itself and reads
  // the frame from a copy: one copy, as with copyBack, and nothing written where nothing changes.
  void copyInputAside(const GBufferLayout& layout) const;  // input() into copyOfInput()
  GLuint copyOfInput() const { return output_.get(); }
  // The copy read as linear light: its sRGB view, which the texture unit decodes (cheaper than pow in a
  // shader); 0 where the display's format has no sRGB twin or the layout says it holds linear values.
  GLuint linearCopyOfInput() const { return linearView_.get(); }
  // DISPLAY_HOLDS_LINEAR for common/display_encoding.glsl, which every pass that mixes or thresholds the
  // display's colours includes: whether the display holds linear light (GBufferLayout::displayEncoding Linear,
  // not an sRGB format), which a pass mixes as stored and thresholds encoded.
  std::string encodingDefine() const;
  uint64_t bytes() const { return bytes_; }

 private:
  GlTexture output_;
  GlTexture encodedCopy_;  // RGBA8 stand-in for an sRGB display; empty otherwise
  GlFramebuffer framebuffer_;
  GlTexture linearView_;  // output_ as GL_SRGB8_ALPHA8; empty unless output_ is GL_RGBA8
  bool linearValues_ = false;
  GlSampler linear_;
  uint64_t bytes_ = 0;
};

}  // namespace retroaa
