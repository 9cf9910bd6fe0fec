// The method registry: one row per method. Adding a method is one file in methods/ (a Technique and
// its factory), one folder of shaders/, the enum value in config.h and one row here (how, in
// docs/architecture.md). Everything else (config parsing, `retroaa config`, the tools' method lists,
// what the plugin allocates) reads this table.
#include "technique.h"

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

namespace {

constexpr uint32_t kSliced = kStorageMsaaGBuffer | kStorageSlices;

// Each row: {{method, name, summary, needs multisampling, least samples, sweep specs, regression spec,
//             tune specs[, stack key]}, storage, factory[, stacked when, storage when stacked, post pass last]}
std::vector<TechniqueRow>& rows() {
  static std::vector<TechniqueRow> table = {
      {{Method::Off, "off", "the host's stock single-sample path; the plugin holds nothing", false, 1, "off", "off",
        "off"},
       kStorageNone,
       nullptr},
      {{Method::Fxaa, "fxaa", "FXAA 3.11 after tonemapping (FreeSpace Open's -aa_preset 0..2)", false, 1, "fxaa",
        "fxaa", "fxaa@fxaa_quality=low,fxaa", "fxaa"},
       kStoragePostTarget,
       createFxaaTechnique,
       [](const Config& c) { return c.fxaa; },
       kStoragePostTarget,
       /*postLast=*/true},
      {{Method::Smaa, "smaa", "SMAA 1x after tonemapping (FreeSpace Open's -post_process_aa, -aa_preset 3..6)", false,
        1, "smaa,resolve+smaa", "smaa", "smaa@smaa_quality=low,smaa@smaa_quality=medium,smaa,smaa@smaa_quality=ultra",
        "smaa"},
       kStoragePostTarget,
       createSmaaTechnique,
       [](const Config& c) { return c.smaa; },
       kStoragePostTarget},
      {{Method::Resolve, "resolve", "MSAA G-buffer and a depth-aware resolve into the host's G-buffer", true, 1,
        "resolve,resolve/front,resolve/back,resolve/fso,resolve/window,resolve/mean,resolve+fxaa", "resolve",
        "resolve@samples=2,resolve,resolve@samples=8,resolve/fso,resolve/window,resolve+fxaa,resolve+coverage"},
       kStorageMsaaGBuffer,
       nullptr},
      {{Method::Coverage, "coverage", "depth-only MSAA prepass and a coverage filter after tonemapping", true, 2,
        "coverage,resolve+coverage", "resolve+coverage", "coverage", "coverage_filter"},
       kStoragePostTarget,
       createCoverageTechnique,
       [](const Config& c) { return c.coverageFilter && usesMsaa(c.method); },
       kStoragePostTarget},
      {{Method::Reconstruct, "reconstruct",
        "depth+normal MSAA prepass; sub-samples rebuilt from neighbouring shaded pixels after tonemapping", true, 2,
        "reconstruct,resolve+reconstruct", "reconstruct",
        "reconstruct@samples=2,reconstruct,reconstruct@samples=8,resolve+reconstruct", "reconstruct_filter"},
       kStoragePostTarget,
       createReconstructTechnique,
       [](const Config& c) { return c.reconstructFilter && usesMsaa(c.method); },
       kStoragePostTarget},
      // The tuner leaves temporal out: it judges single frames, where a history converged on a still
      // camera wins, and a preset must not depend on the host's jitter line (docs/methods/temporal.md).
      {{Method::Temporal, "temporal",
        "jittered projection; each frame blended into a reprojected, neighbourhood-clipped history", false, 1,
        "temporal,resolve+temporal,reconstruct+temporal", "temporal", "", "temporal_filter"},
       kStoragePostTarget,
       createTemporalTechnique,
       [](const Config& c) { return c.temporalFilter; },
       kStoragePostTarget},
      {{Method::Edge, "edge", "edge pixels (a detector decides) lit once per sample through slices", true, 1, "edge",
        "edge", "edge@samples=2,edge,edge@samples=8,edge@edge_detector=plane"},
       kSliced,
       createEdgeTechnique},
      {{Method::Adaptive, "adaptive", "Holländer's metrics choose k samples per pixel, lit through slices", true, 1,
        "adaptive", "adaptive", "adaptive@adaptive_shading_scale=0.5,adaptive,adaptive@adaptive_shading_scale=8"},
       kSliced,
       createAdaptiveTechnique},
      {{Method::Aggregate, "aggregate", "AGAA's clustering: at most c aggregates per pixel, each lit once", true, 1,
        "aggregate", "aggregate", "aggregate@aggregate_count=1,aggregate,aggregate@aggregate_count=3"},
       kSliced,
       createAggregateTechnique},
      {{Method::SmaaS2x, "smaa-s2x",
        "SMAA S2x: SMAA 1x on two single-sample slices of the MSAA G-buffer, each lit by the host, blended 50/50", true,
        2, "smaa-s2x", "smaa-s2x", "smaa-s2x@smaa_quality=medium,smaa-s2x"},
       kSliced,
       createSmaaS2xTechnique},
      {{Method::PerSample, "per-sample", "every sample lit through slices: the quality reference at rate N", true, 1,
        "per-sample", "per-sample", "per-sample@samples=2,per-sample,per-sample@samples=8"},
       kSliced,
       createEdgeTechnique},
      // per-sample's technique in Bayer order (edge.cpp). Regression runs and the tuner leave it out: at m²
      // lights per pixel it is a reference, not a setting.
      {{Method::Ssaa, "ssaa",
        "ordered-grid supersampling: an m x m supersampled G-buffer (supersample=m), every sub-position lit", false, 1,
        "ssaa@supersample=2", "", ""},
       kSliced,
       createEdgeTechnique},
  };
  return table;
}

}  // namespace

const std::vector<TechniqueRow>& techniqueRegistry() { return rows(); }

const TechniqueRow* findTechnique(Method method) {
  for (const TechniqueRow& row : rows())
    if (row.info.method == method) return &row;
  return nullptr;
}

// Post-process AA needs no samples: the best a context without multisampling can do.
Method fallbackWithoutMultisampling() { return Method::Fxaa; }

void registerTechnique(const TechniqueRow& row) { rows().push_back(row); }

const std::vector<MethodInfo>& methodTable() {
  // Rebuilt when a row is registered; the rows are few.
  static std::vector<MethodInfo> infos;
  if (infos.size() != rows().size()) {
    infos.clear();
    for (const TechniqueRow& row : rows()) infos.push_back(row.info);
  }
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
