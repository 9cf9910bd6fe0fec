// A technique: what one method (or one stackable post filter) adds to the shared pieces. Each is one
// row of the registry (registry.cpp) and lives in a file of methods/ with its shaders' folder; related
// methods share a file (edge.cpp: edge, per-sample and ssaa; smaa.cpp: SMAA 1x and S2x), and `resolve`
// is the shared resolve itself (pipeline/), with no technique.
// The plugin owns the shared pieces (MSAA G-buffer, resolve, slices, post target), allocates what
// the active rows ask for, and calls every active technique at the points below.
#pragma once

#include "config_keys.h"
#include "pipeline/pipeline.h"
#include "shared_constants.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace retroaa {

// The shared pieces of the running config; null where no active row asks for them.
struct SharedTargets {
  MsaaGBuffer* msaa = nullptr;
  ResolvePass* resolve = nullptr;
  SliceRenderer* slices = nullptr;
  PostTarget* post = nullptr;
  const ForwardMask* forwardMask = nullptr;  // held while a technique readsForwardMask()
};

class Technique {
 public:
  virtual ~Technique() = default;
  // Slice counts the resolve can write from the samples it reads anyway (`edge`'s detectors); none by default.
  virtual std::optional<ResolveCounts> resolveCounts(PluginContext&, SharedTargets&) { return std::nullopt; }
  // After the resolve into the host's G-buffer, before lighting (e.g. writing the slice mask).
  virtual Status afterResolve(PluginContext&, SharedTargets&, const FrameInfo&) { return Status::ok(); }
  // How the slices light this method (techniques whose row asks for slices). Default: 1 / count
  // weights, sample s in slice s.
  virtual SliceRenderer::Plan slicePlan(PluginContext&, SharedTargets&) { return {}; }
  // After the host's lighting wrote its light target (every slice of it composited), before its tonemap.
  virtual Status afterLighting(PluginContext&, SharedTargets&, const FrameInfo&) { return Status::ok(); }
  // After the host's tonemap, on the post target (techniques whose row asks for it).
  virtual Status post(PluginContext&, SharedTargets&, const FrameInfo&) { return Status::ok(); }
  // A multisampled framebuffer the host draws its models into once more (Plugin::prepassFramebuffer; 0: none).
  virtual GLuint prepassFramebuffer() const { return 0; }
  // Samples of storage the technique holds itself (0: none; the MSAA G-buffer's count otherwise).
  virtual int samples() const { return 0; }
  // Whether budget_ms can steer this technique under `config` (through PluginContext::budgetScale).
  virtual bool followsBudget(const Config&) const { return false; }
  virtual uint64_t bytes() const { return 0; }
  // A method with a history: the sub-pixel offset the host adds to the projection of the frame about to begin
  // (`framesStarted` begun so far; Plugin::jitter), and the mip bias for its material samplers
  // (Plugin::textureLodBias). None and 0 otherwise.
  virtual std::optional<Jitter> jitter(const Config&, uint64_t /*framesStarted*/) const { return std::nullopt; }
  virtual float textureLodBias(const Config&) const { return 0.0f; }
  // Whether post() rebuilds pixels from their neighbours' colours knowing only the opaque surfaces (their
  // depth and normals), so it must leave alone what the host's forward passes drew (ForwardMask).
  virtual bool readsForwardMask() const { return false; }
  // The config changed (Plugin::reconfigure; context.config is the new one): state carried from frame to frame
  // (a history) starts anew where the change alters the image.
  virtual void reconfigured(PluginContext&, const Config& /*previous*/) {}
  // Whether the GL objects built for the config it was created under still serve `config`; if not,
  // the plugin rebuilds the technique. (A new sample count or layout rebuilds every technique.)
  virtual bool keepsObjectsFor(const Config& config) const = 0;
};

// Where a post filter finds each pixel's sub-sample depth (and normals): a multisampled prepass it owns
// and hands the host (Plugin::prepassFramebuffer: depth, and with `withNormals` the output at the
// NormalGloss location, encoded as the layout says), or, stacked on a G-buffer method, the MSAA
// G-buffer's own depth and normals. The prepass methods read their sub-samples through it.
struct SampleGeometry {
  GlTexture depthTexture, normalTexture;  // the prepass's; empty when reading the MSAA G-buffer
  GlFramebuffer prepass;
  GLuint depth = 0, normal = 0;  // what the filter reads (normal 0: none)
  bool packedNormals = false;    // a view-space xyz normal's x and y (the prepass, RG16F), z rebuilt
  bool ownsPrepass = false;
  int requestedSamples = 0, samples = 1;
  std::vector<float> samplePositions;  // x, y per sample, in the pixel (the driver's)
  uint64_t bytes = 0;

  static Result<SampleGeometry> create(PluginContext& context, SharedTargets& shared, bool ownPrepass, bool withNormals,
                                       const std::string& label);
  // Whether the objects still serve `config`, given whether the method owns a prepass under it.
  bool servesConfig(const Config& config, bool ownPrepassUnderConfig) const {
    return ownPrepassUnderConfig == ownsPrepass && (!ownsPrepass || config.samples == requestedSamples);
  }
};

// A post filter over SampleGeometry: it owns the prepass when the config's method is `prepassMethod`
// and reads the MSAA G-buffer when stacked on another.
class SampleGeometryTechnique : public Technique {
 public:
  GLuint prepassFramebuffer() const override { return geometry_.prepass.get(); }
  int samples() const override { return geometry_.samples; }
  uint64_t bytes() const override { return geometry_.bytes; }
  bool readsForwardMask() const override { return readsForwardMask_; }
  bool keepsObjectsFor(const Config& config) const override {
    return geometry_.servesConfig(config, config.method == prepassMethod_);
  }

 protected:
  Status createGeometry(PluginContext& context, SharedTargets& shared, Method prepassMethod, bool withNormals,
                        const std::string& label) {
    prepassMethod_ = prepassMethod;
    auto geometry = SampleGeometry::create(context, shared, context.config.method == prepassMethod, withNormals, label);
    if (!geometry) return geometry.error();
    geometry_ = std::move(geometry.value());
    return Status::ok();
  }
  // A post pass that leaves forward-drawn pixels alone where the layout draws forward passes: its #define
  // (FORWARD_MASK, sampler uForwardDrawn) and, each frame, the mask bound.
  std::string forwardMaskDefine(const GBufferLayout& layout, bool runsAfterForwardPasses) {
    readsForwardMask_ = runsAfterForwardPasses && ForwardMask::appliesTo(layout);
    return defineLine("FORWARD_MASK", readsForwardMask_);
  }
  void bindForwardMask(const ShaderProgram& program, const SharedTargets& shared) const {
    if (readsForwardMask_) program.bindTexture("uForwardDrawn", shared.forwardMask->drawn());
  }
  SampleGeometry geometry_;

 private:
  Method prepassMethod_ = Method::Off;
  bool readsForwardMask_ = false;
};

// What a row needs of the shared pieces (slices imply the MSAA G-buffer).
enum Storage : uint32_t {
  kStorageNone = 0,
  kStorageMsaaGBuffer = 1u << 0,
  kStorageSlices = 1u << 1,
  kStoragePostTarget = 1u << 2,
};

using TechniqueFactory = Result<std::unique_ptr<Technique>> (*)(PluginContext&, SharedTargets&);

// One method: built in registry.cpp with named fields (TechniqueRow::named(...).storage(...)...).
struct TechniqueRow {
  MethodInfo info;          // name, summary, samples, stack key (config.h)
  uint32_t storage;         // Storage bits when this row is the config's method
  TechniqueFactory create;  // null: the shared pieces do all of it
  // Non-null: the row is also active on top of another method when this says so (`resolve+NAME`),
  // needing `stackedStorage` then.
  bool (*stackedOn)(const Config&) = nullptr;
  uint32_t stackedStorage = kStorageNone;
  int minSupersample = 0;  // a supersampled G-buffer of at least this factor (a smaller `supersample` is raised)
  bool postLast = false;   // its post pass runs after every other active technique's
  std::vector<Key> (*keys)() = nullptr;  // its config keys, declared beside it (config_keys.h)
  // Keys declared elsewhere (another technique's, or shared) that this method reads too: every MSAA
  // G-buffer method runs the resolve and reads its keys; smaa-s2x runs SMAA 1x. ConfigKey::methods lists them.
  std::vector<const char*> otherKeys;
  // A method with a history: the frames a still view takes to converge under a config (historyFrames()).
  int (*convergence)(const Config&) = nullptr;

  static TechniqueRow named(Method method, const char* name, const char* summary) {
    TechniqueRow row{};
    row.info.method = method, row.info.name = name, row.info.summary = summary;
    return row;
  }
  TechniqueRow& needsMultisampling(int leastSamples = 1) {
    info.multisampled = true, info.minSamples = leastSamples;
    return *this;
  }
  TechniqueRow& needsSupersampling(int leastFactor) { return minSupersample = leastFactor, *this; }
  TechniqueRow& uses(uint32_t storageBits) { return storage = storageBits, *this; }
  TechniqueRow& createdBy(TechniqueFactory factory) { return create = factory, *this; }
  // Also active on top of another method while `when` holds; `key` is the on/off config key (`+NAME`).
  TechniqueRow& stacks(const char* key, bool (*when)(const Config&), uint32_t storageBits) {
    info.stackKey = key, stackedOn = when, stackedStorage = storageBits;
    return *this;
  }
  TechniqueRow& postPassLast() { return postLast = true, *this; }
  TechniqueRow& configuredBy(std::vector<Key> (*techniqueKeys)()) { return keys = techniqueKeys, *this; }
  TechniqueRow& convergesIn(int (*frames)(const Config&)) { return convergence = frames, *this; }
  TechniqueRow& alsoReads(const std::vector<const char*>& keyNames) {
    otherKeys.insert(otherKeys.end(), keyNames.begin(), keyNames.end());
    return *this;
  }
};

// Every method, in the order listings use.
const std::vector<TechniqueRow>& techniqueRegistry();
// The rows active under `config`: its method's, then every row stacked on it (the post-last ones last).
std::vector<const TechniqueRow*> activeTechniqueRows(const Config& config);
const TechniqueRow* findTechnique(Method method);
// What a method that needs multisampling becomes on a context without it.
Method fallbackWithoutMultisampling();

}  // namespace retroaa
