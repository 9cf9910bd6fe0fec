// `resolve`: MSAA G-buffer → host G-buffer through a depth-aware weighting (shaders/resolve/).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "pipeline.h"

namespace retroaa {

namespace {
// The uniforms resolve.glsl declares, for each of its three programs.
constexpr std::initializer_list<const char*> kResolveUniforms = {RETROAA_GBUFFER_PASS_UNIFORMS, "uSplitByNeighbours",
                                                                 "uFsoFootprintTan", "uCloseness"};
// … and of the counting resolve, which adds edge/detector.glsl's.
constexpr std::initializer_list<const char*> kCountingResolveUniforms = {RETROAA_GBUFFER_PASS_UNIFORMS,
                                                                         "uSplitByNeighbours",
                                                                         "uFsoFootprintTan",
                                                                         "uCloseness",
                                                                         "uDepthCloseness",
                                                                         "uNormalCosine"};
}  // namespace

std::string ResolvePass::defines(const PluginContext& context, const MsaaGBuffer& source, bool withOutputs) const {
  return defineLine("RESOLVE_WEIGHTING", int(weighting_)) + source.shaderDefines(context.layout, withOutputs);
}

Result<std::unique_ptr<ResolvePass>> ResolvePass::create(PluginContext& context, const MsaaGBuffer& source) {
  auto pass = std::make_unique<ResolvePass>();
  const GBufferLayout& layout = context.layout;
  pass->weighting_ = context.config.resolveWeighting;
  for (const bool restore : {false, true}) {
    Result<ShaderProgram> program = context.shaders->program(
        "common/fullscreen.vert", "resolve/resolve.frag",
        (restore ? "#define RESOLVE_RESTORE 1\n" : "") + pass->defines(context, source), kResolveUniforms);
    if (!program) return program.error();
    (restore ? pass->restoreProgram_ : pass->program_) = std::move(program.value());
  }

  // The host's attachments and its depth (not its stencil: those bits belong to the host).
  pass->hostTarget_ = makeFramebuffer(context, "resolve.host_target");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < layout.attachments.size(); ++i) {
    glNamedFramebufferTexture(pass->hostTarget_.get(), GLenum(GL_COLOR_ATTACHMENT0 + i), layout.attachments[i].texture,
                              0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(pass->hostTarget_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
  glNamedFramebufferTexture(pass->hostTarget_.get(), GL_DEPTH_ATTACHMENT, layout.depthStencilTexture, 0);
  if (Status status = checkFramebuffer(pass->hostTarget_.get(), "resolve.host_target"); !status) return status.error();
  if (Status status = pass->createCompute(context, source); !status) return status.error();
  auto check =
      context.shaders->program("common/fullscreen.vert", "resolve/layout_check.frag",
                               source.shaderDefines(layout, false), {RETROAA_DEPTH_ENCODING_UNIFORMS, "uMode"});
  if (!check) return check.error();
  pass->layoutCheck_ = std::move(check.value());
  GLuint queries[2] = {0, 0};
  glGenQueries(2, queries);
  pass->noGeometryQuery_ = GlQuery(context.objects, queries[0]);
  pass->nonPositiveQuery_ = GlQuery(context.objects, queries[1]);
  return pass;
}

namespace {
// Why the compute resolve cannot write this layout (empty: it can).
std::string whyNoComputeResolve(const GBufferLayout& layout) {
  for (size_t i = 0; i < layout.attachments.size(); ++i)
    if (!takesImageStores(layout.attachments[i].internalFormat))
      return "attachment " + std::to_string(i) + "'s format takes no image stores";
  GLint imageUnits = 0, computeImages = 0;
  glGetIntegerv(GL_MAX_IMAGE_UNITS, &imageUnits);
  glGetIntegerv(GL_MAX_COMPUTE_IMAGE_UNIFORMS, &computeImages);
  const int needed = int(layout.attachments.size()) + 1;
  if (std::min(imageUnits, computeImages) < needed)
    return "the context has " + std::to_string(std::min(imageUnits, computeImages)) + " image units for compute, " +
           std::to_string(needed) + " needed";
  return "";
}
}  // namespace

Status ResolvePass::createCompute(PluginContext& context, const MsaaGBuffer& source) {
  computeRequested_ = context.config.resolveCompute;
  if (!computeRequested_) return Status::ok();
  const GBufferLayout& layout = context.layout;
  if (const std::string why = whyNoComputeResolve(layout); !why.empty()) {
    context.warn("resolve_compute=on: " + why + "; using the full-screen pass");
    return Status::ok();
  }
  auto program =
      context.shaders->computeProgram("resolve/resolve.comp", defines(context, source, false), kResolveUniforms);
  if (!program) return program.error();
  if (Status status = createDepthWriter(context); !status) return status;
  computeProgram_ = std::move(program.value());
  resolvedDepth_ = makeTexture(context, GL_R32F, layout.width, layout.height, 0, "resolve.depth", bytes_);
  return Status::ok();
}

Status ResolvePass::createDepthWriter(PluginContext& context) {
  if (writeDepthProgram_.get() != 0) return Status::ok();
  auto writeDepth =
      context.shaders->program("common/fullscreen.vert", "resolve/write_depth.frag", "", {"uResolvedDepth"});
  if (!writeDepth) return writeDepth.error();
  depthTarget_ = makeFramebuffer(context, "resolve.depth_target");
  glNamedFramebufferDrawBuffer(depthTarget_.get(), GL_NONE);
  glNamedFramebufferTexture(depthTarget_.get(), GL_DEPTH_ATTACHMENT, context.layout.depthStencilTexture, 0);
  if (Status status = checkFramebuffer(depthTarget_.get(), "resolve.depth_target"); !status) return status;
  writeDepthProgram_ = std::move(writeDepth.value());
  return Status::ok();
}

void ResolvePass::writeResolvedDepth(PluginContext& context) const {
  context.beginDepthWritingPass(depthTarget_.get());
  writeDepthProgram_.use();
  writeDepthProgram_.bindTexture("uResolvedDepth", resolvedDepth_.get());
  context.drawFullscreen();
}

void ResolvePass::createDepthFloats(PluginContext& context) {
  if (resolvedDepth_.get() != 0) return;
  resolvedDepth_ = makeTexture(context, GL_R32F, context.layout.width, context.layout.height, 0,
                               "resolve.kept_depth_floats", depthFloatBytes_);
  bytes_ += depthFloatBytes_;
}

namespace {
void setResolveInputs(PluginContext& context, const ShaderProgram& program, const MsaaGBuffer& source,
                      const FrameInfo& frame) {
  source.beginPass(program, context, frame);
  const ResolveEvenSplit split = context.config.resolveEvenSplit;
  program.set("uSplitByNeighbours", int(split == ResolveEvenSplit::Neighbours ||
                                        (split == ResolveEvenSplit::Auto && !context.lightsIntoFloats)));
  // FreeSpace Open's footprint: tan(fov / height) with the vertical fov it passes (msaa-f.sdr).
  program.set("uFsoFootprintTan", std::tan(frame.verticalFovRadians / float(context.layout.height)));
  program.set("uCloseness", context.config.closeness);
}

void drawResolve(PluginContext& context, const ShaderProgram& program, const MsaaGBuffer& source,
                 const FrameInfo& frame, const TileDraw& tiles = {}) {
  setResolveInputs(context, program, source, frame);
  context.drawTiles(tiles);
}
}  // namespace

Result<const ShaderProgram*> ResolvePass::countingProgram(PluginContext& context, const MsaaGBuffer& source,
                                                          EdgeDetector detector, bool keepDepth) {
  auto found = countingPrograms_.find({detector, keepDepth});
  if (found != countingPrograms_.end()) return &found->second;
  const int keptDepthLocation = int(context.layout.attachments.size()) + 1;  // after the counts
  Result<ShaderProgram> program = context.shaders->program(
      "common/fullscreen.vert", "resolve/resolve.frag",
      "#define RESOLVE_COUNTS 1\n" + defineLine("EDGE_DETECTOR", int(detector)) +
          (keepDepth ? defineLine("RESOLVE_KEPT_DEPTH_LOCATION", keptDepthLocation) : "") + defines(context, source),
      kCountingResolveUniforms);
  if (!program) return program.error();
  return &countingPrograms_.emplace(std::make_pair(detector, keepDepth), std::move(program.value())).first->second;
}

Result<GLuint> ResolvePass::keepingTarget(PluginContext& context, const MsaaGBuffer& source) {
  if (keepingTarget_) return keepingTarget_.get();
  const GBufferLayout& layout = context.layout;
  Result<ShaderProgram> program = context.shaders->program(
      "common/fullscreen.vert", "resolve/resolve.frag",
      defineLine("RESOLVE_KEPT_DEPTH_LOCATION", int(layout.attachments.size())) + defines(context, source),
      kResolveUniforms);
  if (!program) return program.error();
  keepingProgram_ = std::move(program.value());
  createDepthFloats(context);
  keepingTarget_ = makeFramebuffer(context, "resolve.keeping_target");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i <= layout.attachments.size(); ++i) {
    const GLuint texture = i < layout.attachments.size() ? layout.attachments[i].texture : resolvedDepth_.get();
    glNamedFramebufferTexture(keepingTarget_.get(), GLenum(GL_COLOR_ATTACHMENT0 + i), texture, 0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(keepingTarget_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
  glNamedFramebufferTexture(keepingTarget_.get(), GL_DEPTH_ATTACHMENT, layout.depthStencilTexture, 0);
  if (Status status = checkFramebuffer(keepingTarget_.get(), "resolve.keeping_target"); !status) return status.error();
  return keepingTarget_.get();
}

Result<GLuint> ResolvePass::countingTarget(PluginContext& context, GLuint counts, bool keepDepth) {
  if (countingTarget_ && countingTargetCounts_ == counts && countingTargetKeepsDepth_ == keepDepth)
    return countingTarget_.get();
  const GBufferLayout& layout = context.layout;
  if (keepDepth) createDepthFloats(context);
  countingTarget_ = makeFramebuffer(context, "resolve.counting_target");
  std::vector<GLenum> drawBuffers;
  const size_t n = layout.attachments.size();
  for (size_t i = 0; i <= n + (keepDepth ? 1 : 0); ++i) {
    const GLuint texture = i < n ? layout.attachments[i].texture : i == n ? counts : resolvedDepth_.get();
    glNamedFramebufferTexture(countingTarget_.get(), GLenum(GL_COLOR_ATTACHMENT0 + i), texture, 0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(countingTarget_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
  glNamedFramebufferTexture(countingTarget_.get(), GL_DEPTH_ATTACHMENT, layout.depthStencilTexture, 0);
  if (Status status = checkFramebuffer(countingTarget_.get(), "resolve.counting_target"); !status)
    return status.error();
  countingTargetCounts_ = counts;
  countingTargetKeepsDepth_ = keepDepth;
  return countingTarget_.get();
}

Status ResolvePass::run(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame,
                        const ResolveCounts* counts, bool keepDepthForRestore) {
  wroteCounts_ = false;
  depthFloatsWritten_ = keepDepthForRestore && computes();  // the compute resolve writes them anyway
  {
    // Every sample of every attachment and of the depth read once, one value of each written (and a count).
    uint64_t written = bytesPerTexel(sizedDepthFormat(context.layout.depthStencilTexture));
    for (const Attachment& attachment : context.layout.attachments) written += bytesPerTexel(attachment.internalFormat);
    if (counts && !computes()) written += 1;
    if (keepDepthForRestore && !computes()) written += 4;  // the depth floats (R32F)
    ScopedPass timed(context, "resolve", source.bytes() + written * context.pixelCount());
    if (counts && !computes()) {
      Result<const ShaderProgram*> program = countingProgram(context, source, counts->detector, keepDepthForRestore);
      if (!program) return program.error();
      Result<GLuint> target = countingTarget(context, counts->counts, keepDepthForRestore);
      if (!target) return target.error();
      context.beginDepthWritingPass(target.value());
      const ShaderProgram& counting = *program.value();
      setResolveInputs(context, counting, source, frame);
      counting.set("uDepthCloseness", counts->depthCloseness);
      counting.set("uNormalCosine", counts->normalCosine);
      context.drawFullscreen();
      wroteCounts_ = true;
      depthFloatsWritten_ = keepDepthForRestore;
    } else if (computes()) {
      const GBufferLayout& layout = context.layout;
      setResolveInputs(context, computeProgram_, source, frame);
      std::vector<PluginContext::ImageOutput> outputs;
      for (const Attachment& attachment : layout.attachments)
        outputs.push_back({attachment.texture, attachment.internalFormat});
      outputs.push_back({resolvedDepth_.get(), GL_R32F});
      context.dispatchOverScreen(outputs, kTileSize);
      writeResolvedDepth(context);
    } else if (keepDepthForRestore) {
      Result<GLuint> target = keepingTarget(context, source);
      if (!target) return target.error();
      context.beginDepthWritingPass(target.value());
      drawResolve(context, keepingProgram_, source, frame);
      depthFloatsWritten_ = true;
    } else {
      context.beginDepthWritingPass(hostTarget_.get());
      drawResolve(context, program_, source, frame);
    }
  }
  checkLayout(context, source);
  return Status::ok();
}

void ResolvePass::checkLayout(PluginContext& context, const MsaaGBuffer& source) {
  const GBufferLayout& layout = context.layout;
  if (layoutCheckState_ == LayoutCheck::ToIssue) {
    ScopedPass timed(context, "resolve.layout_check");
    context.beginFullscreenPass(hostTarget_.get());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    layoutCheck_.use();
    source.bind(layout);
    layoutCheck_.setDepthEncoding(context);
    for (int mode = 0; mode < 2; ++mode) {
      layoutCheck_.set("uMode", mode);
      glBeginQuery(GL_SAMPLES_PASSED, mode == 0 ? noGeometryQuery_.get() : nonPositiveQuery_.get());
      context.drawFullscreen();
      glEndQuery(GL_SAMPLES_PASSED);
    }
    layoutCheckState_ = LayoutCheck::Pending;
    return;
  }
  if (layoutCheckState_ != LayoutCheck::Pending) return;
  GLuint available = 0, bothAvailable = 0;
  glGetQueryObjectuiv(noGeometryQuery_.get(), GL_QUERY_RESULT_AVAILABLE, &available);
  glGetQueryObjectuiv(nonPositiveQuery_.get(), GL_QUERY_RESULT_AVAILABLE, &bothAvailable);
  if (!available || !bothAvailable) return;  // a later frame reads them: never a wait in the frame path
  GLuint64 noGeometry = 0, nonPositive = 0;
  glGetQueryObjectui64v(noGeometryQuery_.get(), GL_QUERY_RESULT_NO_WAIT, &noGeometry);
  glGetQueryObjectui64v(nonPositiveQuery_.get(), GL_QUERY_RESULT_NO_WAIT, &nonPositive);
  layoutCheckState_ = LayoutCheck::Done;
  const double pixels = double(context.pixelCount());
  const char* kinds[] = {"Linear", "LogAboveKnee", "FsoCompressedViewZ"};
  const char* depthBufferKinds[] = {"Perspective", "Logarithmic", "ReversedPerspective", "ReversedInfinite",
                                    "PerspectiveClipZeroToOne"};
  const bool fromDepthBuffer = layout.depthSource == DepthSource::DepthBuffer;
  const bool fromWorld = layout.depthSource == DepthSource::WorldPosition;
  const std::string where =
      fromDepthBuffer ? std::string("(GBufferLayout: depthSource DepthBuffer, depthBufferEncoding ") +
                            depthBufferKinds[int(layout.depthBufferEncoding)] + ", FrameInfo near/far planes)"
      : fromWorld ? std::string(
                        "(GBufferLayout: depthSource WorldPosition, ViewPosition attachment, "
                        "depthBufferEncoding ") +
                        depthBufferKinds[int(layout.depthBufferEncoding)] + "; FrameInfo::viewMatrix)"
                  : "(GBufferLayout: ViewPosition attachment, depthChannel=" + std::to_string(layout.depthChannel) +
                        ", depthEncoding " + kinds[int(layout.depthEncoding.kind)] + ")";
  auto percent = [&](GLuint64 count) { return std::to_string(int(std::lround(100.0 * double(count) / pixels))); };
  if (double(nonPositive) > 0.005 * pixels)
    context.warn("layout check: " + percent(nonPositive) + "% of pixels hold geometry at view depth <= 0 " + where +
                 (fromDepthBuffer ? std::string(": is the depth buffer's encoding another (reversed-Z?)")
                  : fromWorld     ? std::string(": is FrameInfo::viewMatrix the world-to-view matrix?")
                                  : std::string(": is the position world-space, or the depth in another channel?")) +
                 " Such samples are treated as background by the resolve and lose their anti-aliasing");
  std::string backgroundRule;
  if (fromDepthBuffer || fromWorld)
    backgroundRule = std::string("the far depth-buffer value, ") +
                     (layout.depthBufferEncoding == DepthBufferEncoding::ReversedPerspective ||
                              layout.depthBufferEncoding == DepthBufferEncoding::ReversedInfinite
                          ? "0"
                          : "1");
  else if (layout.depthEncoding.kind == DepthEncoding::Kind::FsoCompressedViewZ)
    backgroundRule = "decoded depth <= 0.001 m";
  else
    backgroundRule = "stored >= backgroundAbove = " + std::to_string(int(layout.depthEncoding.backgroundAbove));
  if (double(noGeometry) >= 0.99 * pixels)
    context.warn("layout check: " + percent(noGeometry) + "% of pixels have no sample with geometry " + where +
                 ": if the frame shows geometry, its depth reads as background under that encoding (" + backgroundRule +
                 ")" + (fromDepthBuffer || fromWorld ? "" : ", or the depth is in another channel"));
}

bool ResolvePass::restoreNeedsDepthFloats(const PluginContext& context, const SliceRenderer& slices) {
  return context.config.restoreGBufferAfterShade && slices.writesHostDepth() &&
         hasStencil(sizedDepthFormat(context.layout.depthStencilTexture));
}

void ResolvePass::keepForRestore(PluginContext& context, const SliceRenderer& slices) {
  const GBufferLayout& layout = context.layout;
  const GLenum depthFormat = sizedDepthFormat(layout.depthStencilTexture);
  const bool depthFloats = restoreNeedsDepthFloats(context, slices);
  const bool keepDepth = slices.writesHostDepth() && !depthFloats;
  keptThisFrame_ = false;
  if (depthFloats && !depthFloatsWritten_)
    return;  // restore() resolves again: copying the depth back would undo the host's stencil
  if (kept_.empty() || keptDepth_ != keepDepth) {
    kept_.clear();
    bytes_ -= keptBytes_;  // the copies' bytes are counted anew below
    keptBytes_ = 0;
    for (const Attachment& attachment : layout.attachments)
      kept_.push_back(makeTexture(context, attachment.internalFormat, layout.width, layout.height, 0,
                                  "resolve.kept_attachment", keptBytes_));
    if (keepDepth)
      kept_.push_back(
          makeTexture(context, depthFormat, layout.width, layout.height, 0, "resolve.kept_depth", keptBytes_));
    bytes_ += keptBytes_;
    keptDepth_ = keepDepth;
  }
  ScopedPass timed(context, "resolve.keep");
  for (size_t i = 0; i < layout.attachments.size(); ++i)
    copyLayoutTexture(layout, layout.attachments[i].texture, kept_[i].get());
  if (keepDepth) copyLayoutTexture(layout, layout.depthStencilTexture, kept_.back().get());
  keptThisFrame_ = true;
}

Status ResolvePass::restore(PluginContext& context, const MsaaGBuffer& source, const FrameInfo& frame,
                            const SliceRenderer& slices) {
  ScopedPass timed(context, "resolve.restore");
  // Where slice 0 wrote only the pixels lit more than once, the others still hold the resolve: only the
  // tiles of those pixels are drawn.
  const TileDraw overwritten = slices.lastWriteEverywhere() ? TileDraw{} : slices.tilesWhereCountAtLeast(2);
  if (keptThisFrame_) {
    keptThisFrame_ = false;
    const GBufferLayout& layout = context.layout;
    // The resolve's depth floats, written as it wrote them (no stencil test), where the depth was not copied.
    const bool depthFloats = !keptDepth_ && slices.writesHostDepth();
    Result<const ShaderProgram*> program = keptWriter(context, source, depthFloats);
    if (!program) return program.error();
    if (depthFloats)
      context.beginDepthWritingPass(hostTarget_.get());
    else
      context.beginFullscreenPass(hostTarget_.get());
    program.value()->use();
    for (size_t i = 0; i < layout.attachments.size(); ++i) glBindTextureUnit(GLuint(i), kept_[i].get());
    if (depthFloats) glBindTextureUnit(GLuint(layout.attachments.size()), resolvedDepth_.get());
    context.drawTiles(overwritten);
    if (keptDepth_) copyLayoutTexture(layout, kept_.back().get(), layout.depthStencilTexture);
    return Status::ok();
  }
  if (slices.writesHostDepth()) {  // the depth could not be kept: the whole resolve again
    context.beginDepthWritingPass(hostTarget_.get());
    drawResolve(context, program_, source, frame, overwritten);
    return Status::ok();
  }
  // Depth test off: the depth is left as it is. Only where a slice wrote: through the slices' writer
  // (the host's attachments over the count stencil) where count > 1, unless slice 0 wrote everywhere.
  context.beginFullscreenPass(slices.lastWriteEverywhere() ? hostTarget_.get() : slices.writer());
  if (!slices.lastWriteEverywhere()) slices.limitToCountAtLeast(2);
  drawResolve(context, restoreProgram_, source, frame, overwritten);
  return Status::ok();
}

Result<const ShaderProgram*> ResolvePass::keptWriter(PluginContext& context, const MsaaGBuffer& source,
                                                     bool depthFloats) {
  ShaderProgram& program = keptWriters_[depthFloats ? 1 : 0];
  if (program.get() != 0) return &program;
  Result<ShaderProgram> built = context.shaders->program(
      "common/fullscreen.vert", "resolve/restore_kept.frag",
      (depthFloats ? "#define RESTORE_DEPTH_FLOATS 1\n" : "") + source.shaderDefines(context.layout), {});
  if (!built) return built.error();
  program = std::move(built.value());
  return &program;
}

// The config keys of every MSAA G-buffer method's resolve (its registry row lists them: registry.cpp).
std::vector<Key> resolveKeys() {
  return {
      choice("supersample", &Config::supersample, {0, 2, 3, 4},
             "G-buffer methods' source: 0 multisampled (samples); m an m x m supersampled G-buffer (the host's model "
             "pass renders at m x its viewport, Plugin::geometryScale), its m^2 sub-positions lit like samples; "
             "reallocates"),
      named("resolve_weighting", &Config::resolveWeighting, kWeightings,
            "how resolve weights a pixel's samples; free per frame"),
      named("resolve_even_split", &Config::resolveEvenSplit, kEvenSplits,
            "median's pick where a pixel is split 2 of 4 between two surfaces: nearer (right against a radiance "
            "average: a bright near feature dominates), neighbours (against a display average: the surface its 3x3 "
            "neighbourhood says covers more of it), auto (neighbours where the layout lights into its display, "
            "nearer where it lights into floats); free per frame"),
      onOff("resolve_compute", &Config::resolveCompute,
            "the resolve as a compute pass, the depth through a one-fetch full-screen pass (the same G-buffer; for "
            "GPUs whose pixel shaders run on a small partition; where an attachment's format takes no image stores, "
            "the full-screen pass with a warning)"),
      number(
          "closeness", &Config::closeness, 0, 100,
          "c of Eq. 1: samples within min(d1, d2) tan(hfov/width) c of the reference depth are one surface; 0 "
          "keeps the reference sample's alone, larger merges more (past ~20 across real depth steps); free per frame"),
  };
}

}  // namespace retroaa
