// The slice mechanism: lets the host's unchanged lighting light several samples per pixel.
#include <algorithm>

#include "../gl_state.h"
#include "../shared_constants.h"
#include "pipeline.h"

namespace retroaa {

namespace {
void stencilPassWhereCountAbove(int slice) {
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_LESS, slice, 0xFF);  // passes where slice < count
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0x00);
}

}  // namespace

Result<std::unique_ptr<SliceRenderer>> SliceRenderer::create(PluginContext& context, const MsaaGBuffer& source) {
  auto slices = std::make_unique<SliceRenderer>();
  const GBufferLayout& layout = context.layout;
  const int w = layout.width, h = layout.height;
  slices->maxCount_ = source.samples();
  slices->light_ = makeTexture(context, GL_RGBA16F, w, h, 0, "slices.light", slices->bytes_);
  slices->mask_ = makeTexture(context, GL_DEPTH24_STENCIL8, w, h, 0, "slices.mask", slices->bytes_);
  slices->counts_ = makeTexture(context, GL_R8UI, w, h, 0, "slices.counts", slices->bytes_);

  if (Status status = slices->createTargets(context); !status) return status.error();
  if (Status status = slices->createPrograms(context, source); !status) return status.error();
  if (Status status = slices->createTileLists(context); !status) return status.error();
  return slices;
}

Status SliceRenderer::createTileLists(PluginContext& context) {
  const int lists = maxCount_ - 1;
  if (lists < 1) return Status::ok();
  const GBufferLayout& layout = context.layout;
  const int across = tilesAcross_ = (layout.width + kTileSize - 1) / kTileSize;
  const int down = tilesDown_ = (layout.height + kTileSize - 1) / kTileSize;
  std::vector<GLuint> commands;
  for (int list = 0; list < lists; ++list) commands.insert(commands.end(), {6u, 0u, 0u, GLuint(list * across * down)});
  const GLsizeiptr commandBytes = tileCommandBytes_ = GLsizeiptr(commands.size() * sizeof(GLuint));
  tileCommandsReset_ = makeBuffer(context, commandBytes, commands.data(), "slices.tile_commands_reset", bytes_);
  tileCommands_ = makeBuffer(context, commandBytes, commands.data(), "slices.tile_commands", bytes_);
  tileRectangles_ = makeBuffer(context, GLsizeiptr(lists) * across * down * 4 * GLsizeiptr(sizeof(float)), nullptr,
                               "slices.tiles", bytes_);
  tileArray_ = makeRectangleArray(context, tileRectangles_.get(), "slices.tiles");
  tileMaxima_ = makeTexture(context, GL_R8UI, across, down, 0, "slices.tile_maxima", bytes_);
  auto list = context.shaders->computeProgram(
      "slices/list_tiles.comp",
      defineLine("TILE", kTileSize) + defineLine("GROUP", kTileGroup) + defineLine("SAMPLES", maxCount_),
      {"uSliceCounts"});
  if (!list) return list.error();
  listTiles_ = std::move(list.value());
  return Status::ok();
}

void SliceRenderer::listTiles(PluginContext& context) {
  if (!listTiles_.get()) return;
  ScopedPass timed(context, "slices.tiles");
  glCopyNamedBufferSubData(tileCommandsReset_.get(), tileCommands_.get(), 0, 0, tileCommandBytes_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  listTiles_.use();
  listTiles_.bindTexture("uSliceCounts", counts_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, tileCommands_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, tileRectangles_.get());
  context.dispatchOver({{tileMaxima_.get(), GL_R8UI}}, tilesAcross_, tilesDown_, kTileGroup);
  for (GLuint binding : {0u, 1u}) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);  // as for the indirect buffer
  tilesListed_ = true;
}

TileDraw SliceRenderer::limitToCountAtLeast(int minCount) const {
  if (minCount <= 1)
    glDisable(GL_STENCIL_TEST);  // every pixel's count is at least 1
  else
    stencilPassWhereCountAbove(minCount - 1);
  return tilesWhereCountAtLeast(minCount);
}

TileDraw SliceRenderer::tilesWhereCountAtLeast(int minCount) const {
  if (!tilesListed_ || minCount <= 1) return {};
  const int list = std::min(minCount, maxCount_) - 2;  // list t - 1 holds the tiles with a count above t
  return {tileArray_.get(), tileCommands_.get(), GLintptr(list) * 4 * GLintptr(sizeof(GLuint))};
}

// The framebuffers over the mask, the light and the host's targets; the half-float sum where needed.
Status SliceRenderer::createTargets(PluginContext& context) {
  const GBufferLayout& layout = context.layout;
  const int w = layout.width, h = layout.height;
  const bool composes = layout.composedFramebuffer != 0;
  maskTarget_ = makeFramebuffer(context, "slices.mask");
  glNamedFramebufferTexture(maskTarget_.get(), GL_COLOR_ATTACHMENT0, counts_.get(), 0);
  glNamedFramebufferTexture(maskTarget_.get(), GL_DEPTH_STENCIL_ATTACHMENT, mask_.get(), 0);
  lightTarget_ = makeFramebuffer(context, "slices.light");
  glNamedFramebufferTexture(lightTarget_.get(), GL_DEPTH_STENCIL_ATTACHMENT, mask_.get(), 0);
  if (composes) {
    // The host's light textures are the callback's scratch, lit per slice and read by its combine, which
    // composes into light_: light_ is what the slices composite.
    std::vector<GLenum> lightBuffers;
    std::vector<GLuint> hostLights{layout.lightTexture};
    hostLights.insert(hostLights.end(), layout.extraLightTextures.begin(), layout.extraLightTextures.end());
    for (size_t k = 0; k < hostLights.size(); ++k) {
      lightBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + k));
      glNamedFramebufferTexture(lightTarget_.get(), lightBuffers.back(), hostLights[k], 0);
    }
    glNamedFramebufferDrawBuffers(lightTarget_.get(), GLsizei(lightBuffers.size()), lightBuffers.data());
    composeTarget_ = makeFramebuffer(context, "slices.compose");
    glNamedFramebufferTexture(composeTarget_.get(), GL_COLOR_ATTACHMENT0, light_.get(), 0);
    glNamedFramebufferTexture(composeTarget_.get(), GL_DEPTH_STENCIL_ATTACHMENT, mask_.get(), 0);
    if (Status status = checkFramebuffer(composeTarget_.get(), "slices.compose"); !status) return status;
    maskDepthWriter_ = makeFramebuffer(context, "slices.mask_depth_writer");
    glNamedFramebufferTexture(maskDepthWriter_.get(), GL_DEPTH_ATTACHMENT, mask_.get(), 0);
    glNamedFramebufferDrawBuffer(maskDepthWriter_.get(), GL_NONE);
    if (Status status = checkFramebuffer(maskDepthWriter_.get(), "slices.mask_depth_writer"); !status) return status;
  } else {
    glNamedFramebufferTexture(lightTarget_.get(), GL_COLOR_ATTACHMENT0, light_.get(), 0);
  }
  if (!composes && !layout.extraLightTextures.empty()) {
    std::vector<GLenum> lightBuffers{GL_COLOR_ATTACHMENT0};
    for (size_t k = 0; k < layout.extraLightTextures.size(); ++k) {
      const std::string label = "slices.extra_light" + std::to_string(k + 1);
      extraLight_.push_back(makeTexture(context, GL_RGBA16F, w, h, 0, label.c_str(), bytes_));
      lightBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT1 + k));
      glNamedFramebufferTexture(lightTarget_.get(), lightBuffers.back(), extraLight_.back().get(), 0);
      GlFramebuffer composite = makeFramebuffer(context, label.c_str());
      glNamedFramebufferTexture(composite.get(), GL_COLOR_ATTACHMENT0, layout.extraLightTextures[k], 0);
      glNamedFramebufferTexture(composite.get(), GL_DEPTH_STENCIL_ATTACHMENT, mask_.get(), 0);
      if (Status status = checkFramebuffer(composite.get(), label.c_str()); !status) return status;
      extraCompositeTarget_.push_back(std::move(composite));
    }
    glNamedFramebufferDrawBuffers(lightTarget_.get(), GLsizei(lightBuffers.size()), lightBuffers.data());
  }
  // Slices composite into the host's light texture where it holds floats; into a half-float sum of the
  // plugin's otherwise, or where the host names no light texture (it lights into a framebuffer, the
  // window's included), written into the host's target once all slices are in (presentLight). A composing
  // callback may read its composed target's previous frame (SuperTuxKart's screen-space reflections): its
  // slices always sum apart.
  const GLuint outputTexture = sceneColourTexture(layout);
  GLint redType = GL_FLOAT;
  if (outputTexture) glGetTextureLevelParameteriv(outputTexture, 0, GL_TEXTURE_RED_TYPE, &redType);
  if (redType != GL_FLOAT || !outputTexture || composes) {
    accumulation_ = makeTexture(context, GL_RGBA16F, w, h, 0, "slices.accumulation", bytes_);
    if (outputTexture) {
      presentTarget_ = makeFramebuffer(context, "slices.present");
      glNamedFramebufferTexture(presentTarget_.get(), GL_COLOR_ATTACHMENT0, outputTexture, 0);
      if (Status status = checkFramebuffer(presentTarget_.get(), "slices.present"); !status) return status;
    }
    auto present =
        context.shaders->program("common/fullscreen.vert", "slices/present_light.frag", "", {"uAccumulated"});
    if (!present) return present.error();
    presentLight_ = std::move(present.value());
  }
  compositeTarget_ = makeFramebuffer(context, "slices.composite");
  glNamedFramebufferTexture(compositeTarget_.get(), GL_COLOR_ATTACHMENT0,
                            accumulation_ ? accumulation_.get() : outputTexture, 0);
  glNamedFramebufferTexture(compositeTarget_.get(), GL_DEPTH_STENCIL_ATTACHMENT, mask_.get(), 0);
  sliceWriter_ = makeFramebuffer(context, "slices.writer");
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < layout.attachments.size(); ++i) {
    glNamedFramebufferTexture(sliceWriter_.get(), GLenum(GL_COLOR_ATTACHMENT0 + i), layout.attachments[i].texture, 0);
    drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  glNamedFramebufferDrawBuffers(sliceWriter_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
  glNamedFramebufferTexture(sliceWriter_.get(), GL_DEPTH_STENCIL_ATTACHMENT, mask_.get(), 0);
  for (const auto& [fbo, label] : {std::pair{maskTarget_.get(), "slices.mask"},
                                   {lightTarget_.get(), "slices.light"},
                                   {compositeTarget_.get(), "slices.composite"},
                                   {sliceWriter_.get(), "slices.writer"}})
    if (Status status = checkFramebuffer(fbo, label); !status) return status;
  // A host that rebuilds positions from its depth buffer needs each slice's depth there too: a second
  // write into its depth texture alone (the writer's own depth-stencil is the count mask).
  if (layout.depthSource == DepthSource::DepthBuffer || layout.lightingReadsDepth) {
    depthWriter_ = makeFramebuffer(context, "slices.depth_writer");
    glNamedFramebufferTexture(depthWriter_.get(), GL_DEPTH_ATTACHMENT, layout.depthStencilTexture, 0);
    glNamedFramebufferDrawBuffer(depthWriter_.get(), GL_NONE);
    if (Status status = checkFramebuffer(depthWriter_.get(), "slices.depth_writer"); !status) return status;
  }

  return Status::ok();
}

// The slice writers (and their depth-writing variants), the composite and the bitwise mask pass.
Status SliceRenderer::createPrograms(PluginContext& context, const MsaaGBuffer& source) {
  const GBufferLayout& layout = context.layout;
  for (const bool depth : {false, true}) {
    if (depth && !writesHostDepth()) continue;
    auto writeSlice = context.shaders->program(
        "common/fullscreen.vert", "slices/write_slice.frag", writerDefines(source, layout, depth),
        {RETROAA_DEPTH_ENCODING_UNIFORMS, RETROAA_SLICE_DEPTH_UNIFORMS, "uSample"});
    if (!writeSlice) return writeSlice.error();
    (depth ? writeSliceDepth_ : writeSlice_) = std::move(writeSlice.value());
  }
  auto composite =
      context.shaders->program("common/fullscreen.vert", "slices/composite.frag", "", {"uSliceLight", "uSliceCounts"});
  if (!composite) return composite.error();
  composite_ = std::move(composite.value());
  auto mark =
      context.shaders->program("common/fullscreen.vert", "slices/mark_pixels.frag", "", {"uBit", "uSliceCounts"});
  if (!mark) return mark.error();
  markPixels_ = std::move(mark.value());
  if (context.capabilities.stencilExport) {
    auto fromCounts =
        context.shaders->program("common/fullscreen.vert", "slices/stencil_from_counts.frag", "", {"uSliceCounts"});
    if (!fromCounts) return fromCounts.error();
    stencilFromCounts_ = std::move(fromCounts.value());
  }
  if (keepsSliceDepth()) {
    auto copyDepth = context.shaders->program("common/fullscreen.vert", "slices/copy_depth.frag", "", {"uDepth"});
    if (!copyDepth) return copyDepth.error();
    copyDepth_ = std::move(copyDepth.value());
  }
  return Status::ok();
}

void SliceRenderer::clearMask(PluginContext& context, GLuint target, int count) {
  context.beginFullscreenPass(target);
  const GLuint counts[4] = {GLuint(count), 0, 0, 0};
  glClearNamedFramebufferuiv(target, GL_COLOR, 0, counts);
  glDepthMask(GL_TRUE);  // a depth clear obeys the depth write mask
  glStencilMask(0xFF);
  glClearNamedFramebufferfi(target, GL_DEPTH_STENCIL, 0, 1.0f, count);
  glDepthMask(GL_FALSE);
}

void SliceRenderer::stencilFromCounts(PluginContext& context) {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  if (stencilFromCounts_.get()) {
    glStencilMask(0xFF);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // the shader's gl_FragStencilRefARB replaces the reference
    stencilFromCounts_.use();
    stencilFromCounts_.bindTexture("uSliceCounts", counts_.get());
    context.drawFullscreen();
    return;
  }
  // Without stencil export, the count reaches the stencil one bit at a time: pass b sets bit b
  // wherever the count has it. ⌈log2(N+1)⌉ passes, each reading one byte per pixel.
  glStencilFunc(GL_ALWAYS, 0xFF, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  markPixels_.use();
  markPixels_.bindTexture("uSliceCounts", counts_.get());
  for (int bit = 0; (1 << bit) <= maxCount_; ++bit) {
    glStencilMask(GLuint(1) << bit);
    markPixels_.set("uBit", 1 << bit);
    context.drawFullscreen();
  }
}

Status SliceRenderer::writeMask(PluginContext& context, GLuint maskProgram, bool stencilExport, GLuint target) {
  if (target == 0) target = maskTarget_.get();
  clearMask(context, target, 0);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xFF);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // the shader's gl_FragStencilRefARB replaces the reference
  glUseProgram(maskProgram);
  context.drawFullscreen();
  if (!stencilExport) stencilFromCounts(context);
  countsVary_ = true;
  return Status::ok();
}

Status SliceRenderer::writeStencilFromCounts(PluginContext& context) {
  context.beginFullscreenPass(maskTarget_.get());
  glStencilMask(0xFF);
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfi(maskTarget_.get(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glDepthMask(GL_FALSE);
  stencilFromCounts(context);
  countsVary_ = true;
  return Status::ok();
}

void SliceRenderer::writeUniformMask(PluginContext& context, int count) {
  clearMask(context, maskTarget_.get(), count);
  countsVary_ = false;
}

namespace {

// The least slice count of the pixels whose samples slice s writes (0: every pixel; slice 0 leaves single-count
// pixels the resolved G-buffer unless the plan writes it everywhere).
int leastCountLitBy(const SliceRenderer::Plan& plan, int slice) {
  return slice > 0 ? slice + 1 : plan.firstSliceEverywhere ? 0 : 2;
}

}  // namespace

Status SliceRenderer::shade(PluginContext& context, const MsaaGBuffer& source, const ComposingFunction& compose,
                            const Plan& plan, const ForwardTarget* forward) {
  // Slices that light one sample each with the stock writer keep it for the forward passes.
  const bool keepsSamples = forward && !plan.writeProgram && !plan.filterSliceLight;
  const int sliceCount = plan.sliceCount > 0 ? plan.sliceCount : maxCount_;
  context.frameStats.slices = sliceCount;
  lastWriteEverywhere_ = plan.firstSliceEverywhere;
  tilesListed_ = false;
  const bool listsTiles = countsVary_ && context.config.sliceTiles;
  if (listsTiles && !plan.maskAfterFirstSlice) listTiles(context);
  if (keepsSliceDepth()) copyResolvedDepthIntoMask(context);
  GLuint previousPixels = 0;  // the last slice's occlusion query (none for slice 0)
  for (int slice = 0; slice < sliceCount; ++slice) {
    // Slice s + 1's pixels (count > s + 1) are among slice s's: where slice s had none, slice s + 1's write
    // is skipped on the GPU too, and its own query then counts none (no CPU wait).
    const bool chained = previousPixels != 0 && !plan.filterSliceLight;
    if (chained) glBeginConditionalRender(previousPixels, GL_QUERY_WAIT);
    const GLuint slicePixels = writeSlice(context, source, plan, slice);
    if (chained) glEndConditionalRender();
    previousPixels = slicePixels;
    // A slice without pixels (every count of the frame at most `slice`) draws nothing: the GPU skips its
    // lighting and composite on its own query's result, without the CPU waiting for it. A slice whose
    // light is filtered (Plan::filterSliceLight) always has pixels: its first slice writes everywhere.
    const bool skippable = slicePixels != 0 && !plan.filterSliceLight;
    if (skippable) glBeginConditionalRender(slicePixels, GL_QUERY_WAIT);
    lightSlice(context, compose, slice);
    if (slice == 0 && plan.maskAfterFirstSlice) {
      if (Status status = plan.maskAfterFirstSlice(); !status) return status;
      if (listsTiles) listTiles(context);
    }
    const Status composited = compositeSlice(context, plan, slice);
    if (keepsSamples) {  // a pixel one slice lit is that slice's colour in every sample: fill.frag gives it
      const int keptCount = std::max(leastCountLitBy(plan, slice), 2);
      forward->keepSample(context, light_.get(), counts_.get(), keptCount,
                          plan.sampleOrder.empty() ? slice : plan.sampleOrder[size_t(slice)],
                          tilesWhereCountAtLeast(keptCount));
    }
    if (skippable) glEndConditionalRender();
    if (!composited) return composited;
  }
  if (accumulation_) presentAccumulation(context);
  return Status::ok();
}

GLuint SliceRenderer::writeSlice(PluginContext& context, const MsaaGBuffer& source, const Plan& plan, int slice) {
  const GBufferLayout& layout = context.layout;
  ScopedPass timed(context, "slices.write");
  if (!plan.writeProgram) timed.floorReadsSamples(1);  // the stock writer copies one sample of each attachment
  // Where the slices keep their depth, the G-buffer write also writes the mask's depth, under the mask's
  // own stencil: a draw a slice fewer than a depth write of its own limited by the counts (the depth
  // output makes the stencil test late, so the write's shader runs on every pixel of its tiles).
  const bool writesMaskDepth = keepsSliceDepth();
  if (writesMaskDepth)
    context.beginDepthWritingPass(sliceWriter_.get());
  else
    context.beginFullscreenPass(sliceWriter_.get());
  const TileDraw tiles = limitToCountAtLeast(leastCountLitBy(plan, slice));
  auto useWriter = [&](const ShaderProgram* own, const ShaderProgram& stock) {
    const ShaderProgram& program = plan.writeProgram ? *own : stock;
    program.use();
    source.bind(layout);
    if (plan.writeProgram) {
      if (plan.bindWriteInputs) plan.bindWriteInputs(program);
      program.set("uSlice", slice);
    } else {
      program.setDepthEncoding(context);
      program.set("uSample", plan.sampleOrder.empty() ? slice : plan.sampleOrder[size_t(slice)]);
    }
    return &program;
  };
  const ShaderProgram* writer = useWriter(plan.writeProgram, writeSlice_);
  if (writesMaskDepth) {
    writer->set("uMinCount", 0);  // the stencil test limits it
    glBindTextureUnit(kUnitSliceCounts, counts_.get());
  }
  // The write passes exactly where this slice's lighting will run (slice 0 lights every pixel):
  // its occlusion query counts the slice's evaluations, without a pass of its own.
  const bool countOnGpu = slice > 0;
  const GLuint slicePixels = countOnGpu ? context.statistics->beginEvaluationCount() : 0;
  context.drawTiles(tiles);
  if (countOnGpu)
    context.statistics->endEvaluationCount();
  else
    context.statistics->addEvaluations(context.pixelCount());
  // The same pixels' depth, selected by the counts instead of the stencil (the host's depth-stencil has the
  // host's bits), into the host's depth texture: its lighting reads it.
  if (writesHostDepth()) {
    context.beginDepthWritingPass(depthWriter_.get());
    const ShaderProgram* program = useWriter(plan.writeDepthProgram, writeSliceDepth_);
    program->set("uMinCount", leastCountLitBy(plan, slice));
    glBindTextureUnit(kUnitSliceCounts, counts_.get());
    context.drawTiles(tiles);
  }
  return slicePixels;
}

void SliceRenderer::copyResolvedDepthIntoMask(PluginContext& context) {
  ScopedPass timed(context, "slices.depth");
  context.beginDepthWritingPass(maskDepthWriter_.get());
  copyDepth_.use();
  copyDepth_.bindTexture("uDepth", context.layout.depthStencilTexture);
  context.drawFullscreen();
}

void SliceRenderer::lightSlice(PluginContext& context, const ComposingFunction& compose, int slice) {
  ScopedPass timed(context, "slices.lighting");
  GlStateGuard hostState;  // the host's lighting may change anything; the stencil test must hold
  // A host whose lighting only adds (blending ONE, ONE) and clears its target outside the call
  // (SuperTuxKart) finds it black, as its own target would be; so does its combine's target.
  context.beginFullscreenPass(lightTarget_.get());  // before the clears: they obey the colour mask and scissor
  const float black[4] = {0, 0, 0, 0};
  const GLint lightOutputs = 1 + GLint(composeTarget_ ? context.layout.extraLightTextures.size() : extraLight_.size());
  for (GLint buffer = 0; buffer < lightOutputs; ++buffer)
    glClearNamedFramebufferfv(lightTarget_.get(), GL_COLOR, buffer, black);
  if (composeTarget_) glClearNamedFramebufferfv(composeTarget_.get(), GL_COLOR, 0, black);
  limitToCountAtLeast(slice + 1);  // slice s lights the pixels with count > s
  compose({lightTarget_.get(), composeTarget_.get()});
}

Status SliceRenderer::compositeSlice(PluginContext& context, const Plan& plan, int slice) {
  // The light of each output (the host's further outputs after the first), filtered first where the plan
  // filters it: a filter's passes time themselves, outside the composite's.
  std::vector<GLuint> lights{light_.get()};
  for (const GlTexture& extra : extraLight_) lights.push_back(extra.get());
  if (plan.filterSliceLight)
    for (GLuint& light : lights) {
      auto filtered = plan.filterSliceLight(slice, light);
      if (!filtered) return filtered.error();
      light = filtered.value();
    }
  ScopedPass timed(context, "slices.composite");
  for (size_t output = 0; output < lights.size(); ++output) {
    // weight × light into the output's target: slice 0 overwrites the whole target, later slices add.
    context.beginFullscreenPass(output == 0 ? compositeTarget_.get() : extraCompositeTarget_[output - 1].get());
    const TileDraw tiles = limitToCountAtLeast(slice + 1);
    glEnable(GL_FRAMEBUFFER_SRGB);  // an sRGB light target (a display lit directly) adds in linear light
    if (slice > 0) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
    }
    const ShaderProgram& program = plan.compositeProgram ? *plan.compositeProgram : composite_;
    program.use();
    program.bindTexture("uSliceLight", lights[output]);
    if (plan.compositeProgram) {
      if (plan.bindCompositeInputs) plan.bindCompositeInputs();
      program.set("uSlice", slice);
    } else {
      composite_.bindTexture("uSliceCounts", counts_.get());
    }
    context.drawTiles(tiles);
  }
  return Status::ok();
}

void SliceRenderer::presentAccumulation(PluginContext& context) {
  const GBufferLayout& layout = context.layout;
  ScopedPass timed(context, "slices.present");
  glBindFramebuffer(GL_FRAMEBUFFER, presentTarget_.get() ? presentTarget_.get() : sceneColourFramebuffer(layout));
  context.beginFullscreenPass(0);  // 0: the binding above (the host's may be the default framebuffer)
  glEnable(GL_FRAMEBUFFER_SRGB);   // an sRGB target encodes the linear sum
  presentLight_.use();
  presentLight_.bindTexture("uAccumulated", accumulation_.get());
  context.drawFullscreen();
}

std::vector<uint8_t> SliceRenderer::readCounts() const {
  GLint width = 0, height = 0;
  glGetTextureLevelParameteriv(counts_.get(), 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(counts_.get(), 0, GL_TEXTURE_HEIGHT, &height);
  std::vector<uint8_t> counts(size_t(width) * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);  // a host's row length or skips would scatter the rows
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glGetTextureImage(counts_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, GLsizei(counts.size()), counts.data());
  return counts;
}

}  // namespace retroaa
