// The method registry: one row per method. Adding a method is one file in methods/ (a Technique and
// its factory), one folder of shaders/, the enum value in config.h and one row here (how, in
// docs/architecture.md). Everything else (config parsing, `retroaa config`, the tools' method lists,
// what the plugin allocates) reads this table.
#include "technique.h"

#include <algorithm>

namespace retroaa {

// The factories, each defined in its technique's file.
Result<std::unique_ptr<Technique>> createFxaaTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createEdgeTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createAdaptiveTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createAggregateTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createCoverageTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createReconstructTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createSmaaTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createSmaaS2xTechnique(PluginContext&, SharedTargets&);
Result<std::unique_ptr<Technique>> createTemporalTechnique(PluginContext&, SharedTargets&);

// Each technique's config keys, declared in its file.
std::vector<Key> resolveKeys();
std::vector<Key> edgeKeys();
std::vector<Key> adaptiveKeys();
std::vector<Key> aggregateKeys();
std::vector<Key> coverageKeys();
std::vector<Key> reconstructKeys();
std::vector<Key> temporalKeys();
int temporalConvergence(const Config& config);
std::vector<Key> fxaaKeys();
std::vector<Key> smaaKeys();

namespace {

constexpr uint32_t kSliced = kStorageMsaaGBuffer | kStorageSlices;
// The resolve's keys, which every method on the MSAA G-buffer reads: each renders into it and runs the resolve.
const std::vector<const char*> kResolveKeys = {"supersample", "resolve_weighting", "resolve_even_split",
                                               "resolve_compute", "closeness"};

// Built once, on first use, and never changed: every plugin, tool and thread reads one table.
const std::vector<TechniqueRow>& rows() {
  using Row = TechniqueRow;
  static const std::vector<TechniqueRow> table = {
      Row::named(Method::Off, "off", "the host's stock single-sample path; the plugin holds nothing"),
      Row::named(Method::Fxaa, "fxaa", "FXAA 3.11 after tonemapping (FreeSpace Open's -aa_preset 0..2)")
          .uses(kStoragePostTarget)
          .createdBy(createFxaaTechnique)
          .configuredBy(fxaaKeys)
          .stacks(
              "fxaa", [](const Config& c) { return c.fxaa; }, kStoragePostTarget)
          .postPassLast(),
      Row::named(Method::Smaa, "smaa", "SMAA 1x after tonemapping (FreeSpace Open's -post_process_aa, -aa_preset 3..6)")
          .uses(kStoragePostTarget)
          .createdBy(createSmaaTechnique)
          .configuredBy(smaaKeys)
          .stacks(
              "smaa", [](const Config& c) { return c.smaa; }, kStoragePostTarget),
      Row::named(Method::Resolve, "resolve", "MSAA G-buffer and a depth-aware resolve into the host's G-buffer")
          .needsMultisampling()
          .uses(kStorageMsaaGBuffer)
          .configuredBy(resolveKeys),
      Row::named(Method::Coverage, "coverage", "depth-only MSAA prepass and a coverage filter after tonemapping")
          .needsMultisampling(2)
          .uses(kStoragePostTarget)
          .createdBy(createCoverageTechnique)
          .configuredBy(coverageKeys)
          .stacks(
              "coverage_filter", [](const Config& c) { return c.coverageFilter && usesMsaa(c.method); },
              kStoragePostTarget),
      Row::named(Method::Reconstruct, "reconstruct",
                 "depth+normal MSAA prepass; sub-samples rebuilt from neighbouring shaded pixels after tonemapping")
          .needsMultisampling(2)
          .uses(kStoragePostTarget)
          .createdBy(createReconstructTechnique)
          .configuredBy(reconstructKeys)
          .stacks(
              "reconstruct_filter", [](const Config& c) { return c.reconstructFilter && usesMsaa(c.method); },
              kStoragePostTarget),
      Row::named(Method::Temporal, "temporal",
                 "jittered projection; each frame blended into a reprojected, neighbourhood-clipped history")
          .uses(kStoragePostTarget)
          .createdBy(createTemporalTechnique)
          .configuredBy(temporalKeys)
          .convergesIn(temporalConvergence)
          .stacks(
              "temporal_filter", [](const Config& c) { return c.temporalFilter; }, kStoragePostTarget),
      Row::named(Method::Edge, "edge", "edge pixels (a detector decides) lit once per sample through slices")
          .needsMultisampling()
          .uses(kSliced)
          .createdBy(createEdgeTechnique)
          .configuredBy(edgeKeys)
          .alsoReads(kResolveKeys),
      Row::named(Method::Adaptive, "adaptive", "Holländer's metrics choose k samples per pixel, lit through slices")
          .needsMultisampling()
          .uses(kSliced)
          .createdBy(createAdaptiveTechnique)
          .configuredBy(adaptiveKeys)
          .alsoReads(kResolveKeys),
      Row::named(Method::Aggregate, "aggregate", "AGAA's clustering: at most c aggregates per pixel, each lit once")
          .needsMultisampling()
          .uses(kSliced)
          .createdBy(createAggregateTechnique)
          .configuredBy(aggregateKeys)
          .alsoReads(kResolveKeys),
      Row::named(Method::SmaaS2x, "smaa-s2x",
                 "SMAA S2x: SMAA 1x on two single-sample slices of the MSAA G-buffer, each lit by the host, blended "
                 "50/50")
          .needsMultisampling(2)
          .uses(kSliced)
          .createdBy(createSmaaS2xTechnique)
          .alsoReads(kResolveKeys)
          .alsoReads({"smaa_quality", "smaa_edge_detection"}),
      Row::named(Method::PerSample, "per-sample", "every sample lit through slices: the quality reference at rate N")
          .needsMultisampling()
          .uses(kSliced)
          .createdBy(createEdgeTechnique)
          .alsoReads(kResolveKeys),
      // per-sample's technique in Bayer order (edge.cpp).
      Row::named(Method::Ssaa, "ssaa",
                 "ordered-grid supersampling: an m x m supersampled G-buffer (supersample=m), every sub-position lit")
          .needsSupersampling(2)
          .uses(kSliced)
          .createdBy(createEdgeTechnique)
          .alsoReads(kResolveKeys),
  };
  return table;
}

}  // namespace

const std::vector<TechniqueRow>& techniqueRegistry() { return rows(); }

std::vector<const TechniqueRow*> activeTechniqueRows(const Config& config) {
  std::vector<const TechniqueRow*> rows;
  if (const TechniqueRow* own = findTechnique(config.method)) rows.push_back(own);
  for (const TechniqueRow& row : techniqueRegistry())
    if (row.info.method != config.method && row.stackedOn && row.stackedOn(config)) rows.push_back(&row);
  std::stable_partition(rows.begin() + (rows.empty() ? 0 : 1), rows.end(),
                        [](const TechniqueRow* row) { return !row->postLast; });
  return rows;
}

int historyFrames(const Config& config) {
  int frames = 0;
  for (const TechniqueRow* row : activeTechniqueRows(config))
    if (row->convergence) frames = std::max(frames, row->convergence(config));
  return frames;
}

const TechniqueRow* findTechnique(Method method) {
  for (const TechniqueRow& row : techniqueRegistry())
    if (row.info.method == method) return &row;
  return nullptr;
}

// Post-process AA needs no samples: the best a context without multisampling can do.
Method fallbackWithoutMultisampling() { return Method::Fxaa; }

const std::vector<MethodInfo>& methodTable() {
  static const std::vector<MethodInfo> infos = [] {
    std::vector<MethodInfo> built;
    for (const TechniqueRow& row : techniqueRegistry()) {
      built.push_back(row.info);
      built.back().filtersDisplay = row.storage & kStoragePostTarget;
    }
    return built;
  }();
  return infos;
}

const MethodInfo* findMethod(Method method) {
  for (const MethodInfo& info : methodTable())
    if (info.method == method) return &info;
  return nullptr;
}

bool usesMsaa(Method method) {
  const TechniqueRow* row = findTechnique(method);
  return row && (row->storage & kStorageMsaaGBuffer);
}

}  // namespace retroaa
