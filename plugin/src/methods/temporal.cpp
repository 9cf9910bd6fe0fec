// `temporal`: jittered temporal accumulation (Karis, "High Quality Temporal Supersampling", SIGGRAPH
// 2014; Salvi, "An Excursion in Temporal Supersampling", GDC 2016). The host shifts its projection each
// frame by Plugin::jitter() (Halton 2, 3); this technique reprojects the previous output from the
// host's depth and the two frames' matrices, clips it to this frame's neighbourhood and blends this
// frame in (shaders/temporal/). As the method it runs on the stock single-sample path; stacked
// (`temporal_filter=on`) after any other method's own passes. On the display after tonemapping, or on
// the HDR light target before it (temporal_before_tonemap).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "../config_keys.h"
#include "../shared_constants.h"
#include "../technique.h"

namespace retroaa {

namespace {

using Matrix4 = std::array<float, 16>;  // column-major, as GL stores it

Matrix4 toMatrix(const float (&m)[16]) {
  Matrix4 out;
  for (int i = 0; i < 16; ++i) out[size_t(i)] = m[i];
  return out;
}

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
  Matrix4 out{};
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += double(a[size_t(k * 4 + row)]) * b[size_t(column * 4 + k)];
      out[size_t(column * 4 + row)] = float(sum);
    }
  return out;
}

// Gauss-Jordan with partial pivoting, in double (a view matrix far from the origin loses digits in
// float). False for a singular or non-finite matrix.
bool invert(const Matrix4& m, Matrix4& out) {
  double a[4][8];
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) {
      a[row][column] = m[size_t(column * 4 + row)];
      a[row][column + 4] = row == column ? 1.0 : 0.0;
    }
  for (int column = 0; column < 4; ++column) {
    int pivot = column;
    for (int row = column + 1; row < 4; ++row)
      if (std::fabs(a[row][column]) > std::fabs(a[pivot][column])) pivot = row;
    if (!(std::fabs(a[pivot][column]) > 1e-12)) return false;
    for (int k = 0; k < 8; ++k) std::swap(a[column][k], a[pivot][k]);
    const double scale = 1.0 / a[column][column];
    for (int k = 0; k < 8; ++k) a[column][k] *= scale;
    for (int row = 0; row < 4; ++row)
      if (row != column) {
        const double factor = a[row][column];
        for (int k = 0; k < 8; ++k) a[row][k] -= factor * a[column][k];
      }
  }
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) out[size_t(column * 4 + row)] = float(a[row][column + 4]);
  return true;
}

bool allZero(const Matrix4& m) {
  for (float v : m)
    if (v != 0.0f) return false;
  return true;
}

bool allFinite(const Matrix4& m) {
  for (float v : m)
    if (!std::isfinite(v)) return false;
  return true;
}

float halton(uint32_t index, uint32_t base) {
  float fraction = 1.0f, result = 0.0f;
  for (; index > 0; index /= base) {
    fraction /= float(base);
    result += fraction * float(index % base);
  }
  return result;
}

// Point `frame` of the Halton (2, 3) sequence of `length` points, centred on the pixel (frame 1: its first).
Jitter haltonJitter(uint64_t frame, int length) {
  if (length <= 1) return {};
  // Frame 1 takes the sequence's first point, Halton index 1 (index 0 is the pixel's corner).
  const uint32_t index = frame == 0 ? 1u : uint32_t((frame - 1) % uint64_t(length)) + 1;
  return {halton(index, 2) - 0.5f, halton(index, 3) - 0.5f};
}

// Why the layout's light target cannot hold the history's input (empty: it can): the accumulation
// needs one float target that is not the display.
std::string whyNotBeforeTonemap(const GBufferLayout& layout) {
  if (!sceneColourTexture(layout)) return "the layout names no lightTexture";
  if (!layout.composedTexture && !layout.extraLightTextures.empty())
    return "the layout's lighting writes " + std::to_string(1 + layout.extraLightTextures.size()) +
           " outputs (extraLightTextures), which tonemapping combines";
  if (!holdsFloats(sceneColourTexture(layout)))
    return layout.composedTexture ? "the layout's composedTexture holds no floats"
                                  : "the layout's lightTexture holds no floats (lit straight into the display?)";
  return "";
}

class TemporalTechnique : public Technique {
 public:
  static Result<std::unique_ptr<Technique>> create(PluginContext& context, SharedTargets& shared) {
    auto technique = std::make_unique<TemporalTechnique>();
    TemporalTechnique& t = *technique;
    t.jitterOrigin_ = context.statistics->framesStarted();
    const GBufferLayout& layout = context.layout;
    t.beforeTonemapRequested_ = context.config.temporalBeforeTonemap;
    t.jitterLength_ = context.config.temporalJitterLength;
    GLuint output = 0;  // what the pass rewrites: the light target or the display (post's input())
    if (t.beforeTonemapRequested_) {
      if (const std::string why = whyNotBeforeTonemap(layout); why.empty()) {
        t.current_ = makeLightTargetCopy(context, "temporal.current", t.bytes_);
        output = sceneColourTexture(layout);
        t.beforeTonemap_ = true;
      } else {
        // A layout lit straight into the display is a documented pattern (integration.md's window-lit
        // example, the second host): where to accumulate follows from it, said at Info, not warned.
        context.inform("temporal_before_tonemap=on: " + why + "; accumulating the display after tonemapping instead");
      }
    }
    if (!t.beforeTonemap_) {
      output = shared.post->input(layout);
      t.linearInput_ = shared.post->linearCopyOfInput() != 0;
    }
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 2; ++i) {
      t.history_[i] = makeTexture(context, GL_RGBA16F, layout.width, layout.height, 0, "temporal.history", t.bytes_);
      // Read texel by texel (texelFetch); a filter without mipmaps keeps the one-level texture complete.
      glTextureParameteri(t.history_[i].get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glClearTexImage(t.history_[i].get(), 0, GL_RGBA, GL_FLOAT, zero);
      t.framebuffers_[i] = makeFramebuffer(context, "temporal.output");
      glNamedFramebufferTexture(t.framebuffers_[i].get(), GL_COLOR_ATTACHMENT0, output, 0);
      glNamedFramebufferTexture(t.framebuffers_[i].get(), GL_COLOR_ATTACHMENT1, t.history_[i].get(), 0);
      const GLenum drawBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
      glNamedFramebufferDrawBuffers(t.framebuffers_[i].get(), 2, drawBuffers);
      if (Status status = checkFramebuffer(t.framebuffers_[i].get(), "temporal.output"); !status) return status.error();
    }
    // The pass counts its non-finite pixels and its pixels with a short history here; the counts are copied
    // into a buffer mapped once, here (persistent and coherent), and read through the mapping frames later,
    // once a fence says they landed.
    GLuint buffers[2] = {};
    glCreateBuffers(2, buffers);
    const GLuint zeroCounts[kCounters] = {};
    const GLbitfield mapping = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    glNamedBufferStorage(buffers[0], sizeof zeroCounts, zeroCounts, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferStorage(buffers[1], sizeof zeroCounts, zeroCounts, mapping);
    t.counters_ = GlBuffer(context.objects, buffers[0]);
    t.countsReadback_ = GlBuffer(context.objects, buffers[1]);
    t.countsMapped_ = static_cast<const GLuint*>(glMapNamedBufferRange(buffers[1], 0, sizeof zeroCounts, mapping));
    if (!t.countsMapped_)
      return Error{ErrorCode::UnsupportedContext, "temporal: the context could not map its 8-byte readback buffer"};
    t.bytes_ += 2 * sizeof zeroCounts;
    auto program = context.shaders->program(
        "common/fullscreen.vert", "temporal/temporal.frag",
        depthEncodingDefines(layout) + defineLine("LINEAR_INPUT", t.linearInput_) +
            (t.beforeTonemap_ ? defineLine("DISPLAY_HOLDS_LINEAR", true) : shared.post->encodingDefine()) +
            defineLine("HAS_VELOCITY", layout.velocityAttachment >= 0) + "#define MAX_MOVING_OBJECTS " +
            std::to_string(kMaxMovingObjects) + "\n",
        {RETROAA_DEPTH_BUFFER_UNIFORMS, "uViewToPreviousClip", "uProjection", "uClipWPerViewZ", "uBlend",
         "uHistoryValid", "uShortHistoryBlend", "uSampleOffset", "uInput", "uHistory", "uDepth", "uVelocity",
         "uMovingObjects", "uViewToBox", "uObjectViewToPreviousClip"});
    if (!program) return program.error();
    t.program_ = std::move(program.value());
    return std::unique_ptr<Technique>(std::move(technique));
  }

  Status afterLighting(PluginContext& context, SharedTargets&, const FrameInfo& frame) override {
    if (!beforeTonemap_) return Status::ok();
    ScopedPass timed(context, "temporal");
    copyLightTarget(context.layout, current_.get());
    run(context, frame, current_.get());
    return Status::ok();
  }

  Status post(PluginContext& context, SharedTargets& shared, const FrameInfo& frame) override {
    if (beforeTonemap_) return Status::ok();
    ScopedPass timed(context, "temporal");
    shared.post->copyInputAside(context.layout);
    run(context, frame, linearInput_ ? shared.post->linearCopyOfInput() : shared.post->copyOfInput());
    return Status::ok();
  }

  // The history starts anew when the image changes: not for the statistics or the blend weight.
  void reconfigured(PluginContext& context, const Config& previous) override {
    Config sameImage = previous;
    sameImage.measureGpuTime = context.config.measureGpuTime;
    sameImage.temporalBlend = context.config.temporalBlend;
    if (toConfigText(sameImage) == toConfigText(context.config)) return;
    historyValid_ = false;
    jitterOrigin_ = context.statistics->framesStarted();
  }
  // The sequence starts anew with the history: the frame about to begin is its frame framesStarted + 1 - origin.
  // Narrowed to temporal_moving_jitter_scale of the point as the view moves (byHistory).
  std::optional<Jitter> jitter(const Config& config, uint64_t framesStarted) const override {
    const Jitter point = haltonJitter(framesStarted + 1 - jitterOrigin_, jitterLength_);
    const float scale = byHistory(1.0f, config.temporalMovingJitterScale);
    return Jitter{point.x * scale, point.y * scale};
  }
  float textureLodBias(const Config& config) const override {
    return byHistory(config.temporalLodBias, config.temporalMovingLodBias);
  }
  bool keepsObjectsFor(const Config& config) const override {
    return config.temporalBeforeTonemap == beforeTonemapRequested_ && config.temporalJitterLength == jitterLength_;
  }
  uint64_t bytes() const override { return bytes_; }

 private:
  // `still` where the history spans the jitter sequence, `moving` where it is shorter (a pixel moving, its
  // history blended at up to 0.5, or rejected), by the share of such pixels the pass counted (read frames
  // later: the jitter and the mip bias follow the view's motion a few frames behind it).
  float byHistory(float still, float moving) const { return still + (moving - still) * shortHistoryShare_; }

  // Whether this frame can reproject the history: its matrices are given and usable, and the previous
  // frame's were. Warns once per cause.
  bool reprojectable(PluginContext& context, const FrameInfo& frame, Matrix4& viewToPreviousClip, Matrix4& inverseView,
                     Matrix4& previousViewProjection) {
    const Matrix4 view = toMatrix(frame.viewMatrix), projection = toMatrix(frame.projectionMatrix);
    bool usable = true;
    if (allZero(projection)) {
      usable = false;
      warnOnce(context, warnedNoProjection_,
               "temporal: FrameInfo::projectionMatrix is not set, so the history cannot be reprojected; each frame "
               "is shown as rendered (docs/methods/temporal.md)");
    } else if (!allFinite(projection) || !allFinite(view) || !invert(view, inverseView) ||
               !(projection[0] != 0.0f && projection[5] != 0.0f && projection[11] != 0.0f)) {
      usable = false;
      warnOnce(context, warnedBadMatrices_,
               "temporal: FrameInfo's view or projection matrix is singular, not finite or not a perspective "
               "projection; the history is dropped for such frames");
    }
    const bool continues = usable && historyValid_ && !frame.cameraCut;
    if (continues) {
      previousViewProjection = multiply(previousProjection_, previousView_);
      viewToPreviousClip = multiply(previousViewProjection, inverseView);
    }
    historyValid_ = usable;  // the history this frame writes can be reprojected by the next
    previousView_ = view;
    previousProjection_ = projection;
    return continues;
  }

  // The counts the passes since the last copy made, read once the GPU has copied them aside; until then
  // the counters keep counting. No wait in the frame path. Non-finite pixels (NaN or infinite light, history
  // or blend: the shader showed this frame's light there, or 0, and restarted their history) are warned
  // of; the share of pixels with a short history sets the mip bias (textureLodBias).
  void readCounts(PluginContext& context, bool historyContinued) {
    const GLuint pixels = GLuint(context.layout.width) * GLuint(context.layout.height);
    if (historyContinued) framesCountedSinceCopy_ += 1;
    if (countsCopied_.pending()) {
      if (!countsCopied_.signaled()) return;
      countsCopied_.reset();
      const GLuint nonFinite = countsMapped_[kNonFiniteCounter];
      if (nonFinite > 0)
        warnOnce(context, warnedNonFinite_,
                 "temporal: " + std::to_string(nonFinite) +
                     " pixels were not finite (NaN or infinite light, history or blend); they showed the frame's "
                     "light (0 where it was not finite) and their history restarted");
      if (framesCountedInCopy_ > 0)
        shortHistoryShare_ =
            std::min(1.0f, float(countsMapped_[kShortHistoryCounter]) / (float(framesCountedInCopy_) * float(pixels)));
    }
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(counters_.get(), countsReadback_.get(), 0, 0, kCounters * sizeof(GLuint));
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    const GLuint zero = 0;
    glClearNamedBufferData(counters_.get(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    countsCopied_.insert();
    framesCountedInCopy_ = framesCountedSinceCopy_;
    framesCountedSinceCopy_ = 0;
  }

  // The frame's moving objects as the shader takes them, the nearest kMaxMovingObjects: this view to each
  // box's [-1, 1]³ (where a pixel's surface is inside it), and this view to the previous clip through the
  // object's own motion. Objects whose transforms are singular or not finite are left out (warned once).
  int movingObjects(PluginContext& context, const FrameInfo& frame, const Matrix4& inverseView,
                    const Matrix4& previousViewProjection, std::vector<float>& viewToBox,
                    std::vector<float>& objectViewToPreviousClip) {
    std::vector<std::pair<float, size_t>> byDistance;  // the box centre's squared distance from the camera
    const Matrix4 view = toMatrix(frame.viewMatrix);
    for (size_t i = 0; i < frame.movingObjects.size(); ++i) {
      const float* m = frame.movingObjects[i].boxToWorld;
      float centre[3];
      for (int r = 0; r < 3; ++r)
        centre[r] = view[r] * m[12] + view[4 + r] * m[13] + view[8 + r] * m[14] + view[12 + r];
      byDistance.push_back({centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2], i});
    }
    std::sort(byDistance.begin(), byDistance.end());
    if (byDistance.size() > size_t(kMaxMovingObjects))
      warnOnce(context, warnedTooManyObjects_,
               "temporal: " + std::to_string(byDistance.size()) + " moving objects in one frame; the nearest " +
                   std::to_string(kMaxMovingObjects) + " keep their motion, the rest reproject with the camera");
    int count = 0;
    for (const auto& [distance, index] : byDistance) {
      if (count == kMaxMovingObjects) break;
      const MovingObject& object = frame.movingObjects[index];
      const Matrix4 box = toMatrix(object.boxToWorld), previousBox = toMatrix(object.previousBoxToWorld);
      Matrix4 worldToBox{};
      if (!allFinite(box) || !allFinite(previousBox) || !invert(box, worldToBox)) {
        warnOnce(context, warnedBadObject_,
                 "temporal: a moving object's box transform is singular or not finite; it reprojects with the camera");
        continue;
      }
      const Matrix4 toBox = multiply(worldToBox, inverseView);
      const Matrix4 toPrevious = multiply(multiply(previousViewProjection, previousBox), toBox);
      viewToBox.insert(viewToBox.end(), toBox.begin(), toBox.end());
      objectViewToPreviousClip.insert(objectViewToPreviousClip.end(), toPrevious.begin(), toPrevious.end());
      ++count;
    }
    return count;
  }

  static void warnOnce(PluginContext& context, bool& warned, const std::string& message) {
    if (warned) return;
    warned = true;
    context.warn(message);
  }

  // The pass: `input` (this frame) on unit 0, the previous history on 1, the host's depth on 2; the
  // output and the next history written together.
  void run(PluginContext& context, const FrameInfo& frame, GLuint input) {
    const GBufferLayout& layout = context.layout;
    Matrix4 viewToPreviousClip{}, inverseView{}, previousViewProjection{};
    const bool valid = reprojectable(context, frame, viewToPreviousClip, inverseView, previousViewProjection);
    std::vector<float> viewToBox, objectViewToPreviousClip;
    const int objects =
        valid ? movingObjects(context, frame, inverseView, previousViewProjection, viewToBox, objectViewToPreviousClip)
              : 0;
    const int previous = historyIndex_, next = 1 - historyIndex_;
    context.beginFullscreenPass(framebuffers_[next].get());
    program_.use();
    program_.bindTexture("uInput", input);
    program_.bindTexture("uHistory", history_[previous].get());
    program_.bindTexture("uDepth", layout.depthStencilTexture);
    if (layout.velocityAttachment >= 0)
      program_.bindTexture("uVelocity", layout.attachments[size_t(layout.velocityAttachment)].texture);
    for (const char* filtered : {"uInput", "uHistory"})  // their textures' own filtering: no post pass's sampler
      if (const int unit = program_.unit(filtered); unit >= 0) glBindSampler(GLuint(unit), 0);
    program_.setMatrix4("uViewToPreviousClip", viewToPreviousClip.data());
    program_.set("uMovingObjects", objects);
    if (objects > 0) {
      program_.setMatrix4Array("uViewToBox", objects, viewToBox.data());
      program_.setMatrix4Array("uObjectViewToPreviousClip", objects, objectViewToPreviousClip.data());
    }
    const Matrix4& projection = previousProjection_;  // this frame's, as reprojectable() keeps it
    const float projectionTerms[4] = {projection[0], projection[5], projection[8], projection[9]};
    program_.setVec4("uProjection", projectionTerms);  // P[0][0], P[1][1], P[2][0], P[2][1]
    program_.set("uClipWPerViewZ", projection[11]);    // P[2][3]
    // Where this frame's samples lie from their pixels' centres: the jitter the host shifted its projection
    // by moves the image against it under a right-handed view (clip w = -z) and with it under a left-handed one.
    // (The frame drawn now is the one jitter() answered for before it began, one frame fewer started.)
    const Jitter shift = *jitter(context.config, context.statistics->framesStarted() - 1);
    program_.set("uSampleOffset", -projection[11] * shift.x, -projection[11] * shift.y);
    // A new history averages its first frames evenly (1/n) until temporal_blend takes over: a cut or a
    // reset converges in a few frames instead of fading in over ~2/blend.
    program_.set("uBlend", valid ? std::max(context.config.temporalBlend, 1.0f / float(framesAccumulated_ + 1)) : 1.0f);
    program_.set("uHistoryValid", valid ? 1.0f : 0.0f);
    // An exponential history of weight w holds about 2 / w - 1 frames: shorter than the jitter sequence
    // from 2 / (length + 1) on, too short to average the sharper mips over it.
    program_.set("uShortHistoryBlend", 2.0f / float(jitterLength_ + 1));
    program_.setDepthPlanes(context);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, counters_.get());
    context.drawFullscreen();  // the public call's state guard (shade()'s before tonemapping, post()'s after) gives the
                               // host its atomic-counter binding back
    readCounts(context, valid);
    historyIndex_ = next;
    framesAccumulated_ = valid ? framesAccumulated_ + 1 : 1;
  }

  ShaderProgram program_;
  GlTexture history_[2];  // RGBA16F: linear colour, view depth in w; ping-pong
  GlFramebuffer framebuffers_[2];
  GlTexture current_;  // before tonemapping: this frame's light, read while the target is written
  int historyIndex_ = 0;
  bool beforeTonemap_ = false;           // on the light target (asked for, and the layout allows it)
  bool beforeTonemapRequested_ = false;  // temporal_before_tonemap as created
  bool linearInput_ = false;
  int jitterLength_ = 8;
  uint64_t jitterOrigin_ = 0;  // frames begun when the sequence (re)started
  bool historyValid_ = false;  // false: the next frame starts a new history (reset, or unusable matrices)
  int framesAccumulated_ = 0;  // frames in the history since it started
  Matrix4 previousView_{}, previousProjection_{};
  // The pass's counts (temporal.frag's atomic counters, in this order) and their copy.
  static constexpr int kNonFiniteCounter = 0, kShortHistoryCounter = 1, kCounters = 2;
  GlBuffer counters_, countsReadback_;
  const GLuint* countsMapped_ = nullptr;  // the readback buffer, mapped for the technique's life
  GlFence countsCopied_;                  // pending: the copy is not yet read
  int framesCountedSinceCopy_ = 0;        // frames with a history counted since the last copy
  int framesCountedInCopy_ = 0;           // … in the copy pending
  float shortHistoryShare_ = 0.0f;        // of the pixels counted in the last copy read
  bool warnedNoProjection_ = false, warnedBadMatrices_ = false, warnedNonFinite_ = false;
  bool warnedTooManyObjects_ = false, warnedBadObject_ = false;
  uint64_t bytes_ = 0;
};

}  // namespace

// The frames a still view takes to converge (its row's convergesIn, read by historyFrames()): two rounds of
// the jitter sequence, and 4 / temporal_blend frames (the history's weight of its first frame then below
// e^-4, 2 %).
int temporalConvergence(const Config& config) {
  return std::max(2 * config.temporalJitterLength, int(std::ceil(4.0f / config.temporalBlend)));
}

Result<std::unique_ptr<Technique>> createTemporalTechnique(PluginContext& context, SharedTargets& shared) {
  return TemporalTechnique::create(context, shared);
}

// The config keys of `temporal` and `+temporal` (its registry row lists them: registry.cpp).
std::vector<Key> temporalKeys() {
  return {
      onOff("temporal_filter", &Config::temporalFilter,
            "temporal accumulation on top of another method (resolve+temporal): the host "
            "jitters its projection by Plugin::jitter()"),
      number("temporal_blend", &Config::temporalBlend, 0.02f, 1,
             "the current frame's weight in the history; smaller is smoother and converges over more "
             "frames (about 2/weight), ghosting longer; 1 keeps no history; free per frame"),
      integer("temporal_jitter_length", &Config::temporalJitterLength, 1, 64,
              "frames in the Halton (2, 3) jitter sequence, the sub-pixel positions a still pixel is "
              "sampled at; 1 is no jitter; resets the history"),
      number("temporal_lod_bias", &Config::temporalLodBias, -3, 0,
             "the mip bias the host adds to its material samplers (Plugin::textureLodBias) where the view is "
             "still: sharper mips whose detail the history averages over the jitter; FSR 2 advises -1 at "
             "native resolution"),
      number("temporal_moving_lod_bias", &Config::temporalMovingLodBias, -3, 0,
             "the mip bias where the view moves: a moving pixel's history is shorter than the jitter sequence, "
             "too short to average sharper mips, whose aliasing then pulses with the jitter; the bias goes "
             "from temporal_lod_bias to this with the share of such pixels, counted frames later"),
      number("temporal_moving_jitter_scale", &Config::temporalMovingJitterScale, 0, 1,
             "the jitter's amplitude where the view moves, as a share of the still view's: a moving pixel's "
             "history is too short to average the jitter's phases; goes from 1 to this with the share of such "
             "pixels, counted frames later"),
      onOff("temporal_before_tonemap", &Config::temporalBeforeTonemap,
            "temporal on the HDR light target before tonemapping (radiance, as the ground truth averages) rather "
            "than on the display (where the layout has no single float light target, after tonemapping, said in "
            "the log at Info); resets the history"),
  };
}

}  // namespace retroaa
