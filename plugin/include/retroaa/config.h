// retroaa's settings: one plain struct, every field with its default, range and cost to change.
// The same keys are read from config files (`key=value` lines), the command line, the
// RETROAA_SETTINGS environment variable and FreeSpace Open's own flags (-msaa, -aa_preset).
// docs/config.md is the reference, generated from the same table as the parser.
#pragma once

#include "retroaa/export.h"
#include "retroaa/result.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace retroaa {

enum class Method : uint8_t {
  Off,          // the host's stock single-sample path; the plugin holds nothing (1 lighting eval/pixel)
  Fxaa,         // Lottes' FXAA after tonemapping (1 eval/pixel)
  Resolve,      // MSAA G-buffer + depth-aware resolve into the host's G-buffer (1 eval/pixel)
  Edge,         // Thibieroz: edge pixels lit once per sample, the rest once (1 + (N-1)·edge fraction)
  PerSample,    // every sample of every pixel lit: the quality reference at rate N (N evals/pixel)
  Adaptive,     // Holländer et al.: k samples per pixel from geometry and shading metrics (1 + Σ(k−1)/pixels)
  Aggregate,    // Crassin et al. (AGAA): ≤ c aggregates per pixel, each lit once, weighted by coverage
  Coverage,     // Pettineo: depth-only MSAA prepass, stock single-sample path, coverage filter after tonemapping (1)
  Reconstruct,  // SRAA-style: depth+normal MSAA prepass, stock single-sample shading, sub-samples rebuilt from
                // neighbouring shaded pixels after tonemapping (1)
  Smaa,         // Jimenez et al.: SMAA 1x after tonemapping (FreeSpace Open's -post_process_aa, -aa_preset 3..6) (1)
  SmaaS2x,      // SMAA S2x: SMAA 1x on two single-sample slices of the MSAA G-buffer, blended 50/50 (2)
  Ssaa,         // ordered-grid supersampling: an m×m supersampled G-buffer, every sub-position lit (m²)
  Temporal,     // Karis-style TAA: the stock path with a jittered projection (Plugin::jitter), each frame blended
                // into a reprojected, neighbourhood-clipped history (1)
};

// How `edge` decides that a pixel's samples see more than one surface.
enum class EdgeDetector : uint8_t {
  Depth,       // any sample's depth off sample 0's by more than Eq. 1 with c = edge_depth_closeness
  Plane,       // Lauritzen: off sample 0's depth plane by more than |dz/dx|+|dz/dy|, or normals < 0.99
  Normal,      // any sample's normal more than edge_normal_angle_deg from sample 0's
  Material,    // any sample's albedo, specular or gloss differs from sample 0's
  Coverage,    // samples not all written by one primitive (any attribute differs bit for bit):
               // the centroid trick without touching the host's shaders; exact, so the default
  EveryPixel,  // marks every pixel (diagnostic: equals per-sample)
};

enum class ResolveWeighting : uint8_t {
  Median,  // Magnussen: samples close (Eq. 1) to the median depth sample; the default
  Front,   // samples close to the nearest sample
  Back,    // samples close to the farthest sample (background counts as farthest)
  Fso,     // FreeSpace Open's msaa-f.sdr as it runs: its median, its (asymmetric) smoothstep weights
  Mean,    // naive average of all geometry samples: the failure mode, kept for comparison
  Window,  // the farther of the two middle samples (background farthest), with a smooth window around it: full
           // weight within ±2.5 footprints, none past ±5
};

// How the default `median` weighting decides a pixel split evenly between two surfaces (2 of 4 samples on
// each), which its own samples cannot: which surface is right depends on whether the pixel is judged by
// the average of its radiance (a bright near feature dominates) or of its display values (the surface
// covering more of it).
enum class ResolveEvenSplit : uint8_t {
  Auto,        // `neighbours` where the layout lights into its display, `nearer` where it lights into floats
  Nearer,      // the nearer middle sample
  Neighbours,  // the surface the pixel's 3x3 neighbourhood says covers more of it (the farther where it cannot say)
};

enum class FxaaQuality : uint8_t {
  Low,     // FXAA 3.11 preset 10: 3 search steps
  Medium,  // preset 20: 6 search steps
  High,    // preset 39: 12 search steps (FreeSpace Open's -aa_preset 2)
};

// SMAA's presets: the paper's (and its reference's) threshold, search lengths and corner rounding.
enum class SmaaQuality : uint8_t {
  Low,     // threshold 0.15, 4 search steps (8 px each way), no diagonals, no corner rounding
  Medium,  // threshold 0.1, 8 steps (16 px), no diagonals, no corner rounding
  High,    // threshold 0.1, 16 steps (32 px), 8 diagonal steps, corner rounding 25 %
  Ultra,   // threshold 0.05, 32 steps (64 px), 16 diagonal steps, corner rounding 25 %
};

// What SMAA's first pass finds edges in.
enum class SmaaEdgeDetection : uint8_t {
  Luma,    // luma contrast of the tonemapped colour (the reference's default)
  Colour,  // the largest per-channel contrast: finds chroma-only edges luma misses
  Depth,   // relative steps in the host's view depth: geometry edges only, no texture or shading edges
};

// Every field is one config key, named beside it. What a key does, its range and what changing it costs are
// written once, where the key is declared (a technique's keys in its own file under plugin/src/methods/ or
// pipeline/, the shared ones in plugin/src/config_table.cpp), and read from there by configKeys(),
// `retroaa config`, docs/config.md and the viewer; the default is the initialiser here.
struct Config {
  Method method = Method::Off;  // `method`
  // The G-buffer: its samples, its source, and how the host's model pass shades it.
  int samples = 4;                   // `samples`
  int supersample = 0;               // `supersample` (the host's model pass renders at Plugin::geometryScale())
  float sampleShading = 0.0f;        // `sample_shading` (the host applies Plugin::sampleShading())
  float cutOutSampleShading = 1.0f;  // `cutout_sample_shading` (the host applies Plugin::cutOutDrawSettings())
  // The resolve, which every MSAA G-buffer method runs.
  ResolveWeighting resolveWeighting = ResolveWeighting::Median;  // `resolve_weighting`
  ResolveEvenSplit resolveEvenSplit = ResolveEvenSplit::Auto;    // `resolve_even_split`
  bool resolveCompute = false;                                   // `resolve_compute`
  float closeness = 5.0f;                                        // `closeness`
  // `edge`.
  EdgeDetector edgeDetector = EdgeDetector::Coverage;  // `edge_detector`
  float edgeDepthCloseness = 1.0f;                     // `edge_depth_closeness`
  float edgeNormalAngleDegrees = 25.0f;                // `edge_normal_angle_deg`
  // `adaptive` (Holländer et al. 2013): k = clamp(max(k_d, k_n, k_s, k_t), adaptive_min_samples, N).
  float adaptiveDepthScale = 0.5f;       // `adaptive_depth_scale`
  float adaptiveNormalScale = 8.0f;      // `adaptive_normal_scale`
  float adaptiveShadingScale = 2.0f;     // `adaptive_shading_scale`
  float adaptiveTextureScale = 16.0f;    // `adaptive_texture_scale`
  float adaptiveThresholdMin = 0.0312f;  // `adaptive_threshold_min`
  float adaptiveThresholdEdge = 0.125f;  // `adaptive_threshold_edge`
  int adaptiveMinSamples = 1;            // `adaptive_min_samples`
  // `aggregate` (Crassin et al. 2016).
  int aggregateCount = 2;           // `aggregate_count`
  float aggregateThreshold = 0.1f;  // `aggregate_threshold`
  float aggregateLength = 4.0f;     // `aggregate_length`
  // `coverage`, and its filter stacked on a G-buffer method (`resolve+coverage`).
  bool coverageFilter = false;     // `coverage_filter`
  float coverageTolerance = 2.0f;  // `coverage_tolerance`
  // `reconstruct`, and its filter stacked on a G-buffer method (`resolve+reconstruct`).
  bool reconstructFilter = false;         // `reconstruct_filter`
  float reconstructTolerance = 2.0f;      // `reconstruct_tolerance`
  int reconstructSearchRadius = 6;        // `reconstruct_search_radius`
  bool reconstructBeforeTonemap = false;  // `reconstruct_before_tonemap`
  bool reconstructCompute = false;        // `reconstruct_compute`
  // `temporal`, and its accumulation stacked on another method (`resolve+temporal`): the host jitters its
  // projection by Plugin::jitter() and biases its material samplers by Plugin::textureLodBias().
  bool temporalFilter = false;             // `temporal_filter`
  float temporalBlend = 0.1f;              // `temporal_blend`
  int temporalJitterLength = 8;            // `temporal_jitter_length`
  float temporalLodBias = -1.0f;           // `temporal_lod_bias`
  float temporalMovingLodBias = -0.5f;     // `temporal_moving_lod_bias`
  float temporalMovingJitterScale = 0.5f;  // `temporal_moving_jitter_scale`
  bool temporalBeforeTonemap = true;       // `temporal_before_tonemap`
  // Shared by every method.
  bool restoreGBufferAfterShade = true;  // `restore_gbuffer_after_shade`
  bool sliceTiles = true;                // `slice_tiles`
  float budgetMs = 0.0f;                 // `budget_ms`
  // `fxaa`, and FXAA stacked on any method (`resolve+fxaa`; FreeSpace Open users combine -msaa and FXAA).
  bool fxaa = false;                            // `fxaa`
  FxaaQuality fxaaQuality = FxaaQuality::High;  // `fxaa_quality`
  float fxaaEdgeThreshold = 0.125f;             // `fxaa_edge_threshold`
  // `smaa`, SMAA 1x stacked on any lighting-stage method (`resolve+smaa`), and `smaa-s2x`.
  bool smaa = false;                                              // `smaa`
  SmaaQuality smaaQuality = SmaaQuality::High;                    // `smaa_quality`
  SmaaEdgeDetection smaaEdgeDetection = SmaaEdgeDetection::Luma;  // `smaa_edge_detection`
  // For modders and measurements.
  std::string shaderOverrideDirectory;  // `shader_override_dir`
  bool measureGpuTime = false;          // `measure_gpu_time` (Plugin::stats(), Plugin::waitForStats())
  bool measurePassFloors = false;       // `measure_pass_floors`: each measured pass's floor (adds GPU work)
};

// One settable key, for documentation, parsers and UIs: name, default, allowed values, effect.
struct ConfigKey {
  enum class Kind : uint8_t {
    Number,   // a float in [minimum, maximum]
    Integer,  // an integer in [minimum, maximum]
    Choice,   // one of settingValues(name)
    Switch,   // on or off
    Text,     // free text (a folder)
  };
  const char* name;
  const char* defaultValue;  // as text: what Config{} holds
  const char* allowed;       // as text: "0 .. 100", "on, off", "median, front, back, …"
  const char* effect;        // one line: what it changes and what changing it costs
  Kind kind;
  float minimum, maximum;  // Number and Integer
  // The methods that read it, by name (registry order): the one that declares it and those that read it
  // too (every MSAA G-buffer method reads the resolve's keys); empty for a key every method reads.
  std::vector<const char*> methods;
};
RETROAA_API const std::vector<ConfigKey>& configKeys();

// One method as the plugin's registry lists it (plugin/src/registry.cpp: one row per method). Parsers,
// `retroaa config` and the tools read their method lists from here.
struct MethodInfo {
  Method method = Method::Off;
  const char* name = "";        // as config files, the command line and reports spell it
  const char* summary = "";     // what it does, in one line
  bool multisampled = false;    // needs GL_MAX_SAMPLES >= 2; falls back to fxaa (with a warning) without
  int minSamples = 1;           // fewer samples are raised to this, with a warning
  bool filtersDisplay = false;  // its post pass filters the host's display: the layout needs a display target
  // The on/off key that stacks this method's post pass on another method (`resolve+NAME` in specs);
  // empty where it does not stack.
  const char* stackKey = "";
};
// Every method, in listing order.
RETROAA_API const std::vector<MethodInfo>& methodTable();
// The row of `method`; null for a value no row has.
RETROAA_API const MethodInfo* findMethod(Method method);

// Whether the method renders the model pass into a multisampled G-buffer.
RETROAA_API bool usesMsaa(Method method);
// Frames a still view takes, under `config`, to converge after a switch, a reset or a camera cut: 0 for
// a method that keeps no history. What a capture or a screenshot waits before it is taken.
RETROAA_API int historyFrames(const Config& config);

RETROAA_API const char* toString(Method method);
RETROAA_API const char* toString(ResolveWeighting weighting);
RETROAA_API const char* toString(ResolveEvenSplit split);
RETROAA_API const char* toString(FxaaQuality quality);
RETROAA_API const char* toString(EdgeDetector detector);
RETROAA_API const char* toString(SmaaQuality quality);
RETROAA_API const char* toString(SmaaEdgeDetection detection);

// The value of one key as toConfigText writes it; empty for an unknown key.
RETROAA_API std::string readSetting(const Config& config, const std::string& key);
// The values a key with a fixed set allows, in order (method, samples, resolve_weighting, ...; on/off
// switches); empty for numeric ranges and folders. UIs cycle and list these.
RETROAA_API std::vector<std::string> settingValues(const std::string& key);
// Sets one key; unknown keys and bad values are errors naming the key, the value and what is allowed.
RETROAA_API Status applySetting(Config& config, const std::string& key, const std::string& value);
// `key=value` lines; '#' starts a comment. Errors name the source and line.
RETROAA_API Status applyConfigText(Config& config, const std::string& text, const std::string& sourceName);
RETROAA_API Status applyConfigFile(Config& config, const std::string& path);
// Comma- or semicolon-separated key=value pairs, as in RETROAA_SETTINGS.
RETROAA_API Status applySettingsList(Config& config, const std::string& list, const std::string& sourceName);
// FreeSpace Open's flags: `-msaa 0|4|8|16` (others warn and mean 0; N>0 selects `resolve` unless a
// multi-sample method is already chosen) and
// `-aa_preset 0..6` (0-2 FXAA low/medium/high, 3-6 SMAA low/medium/high/ultra, as in FSO; stacked as
// `+fxaa`/`+smaa` on a multi-sample method; the last one wins) and `-post_process_aa` (value ignored:
// SMAA low unless a preset chose a filter). `warnings` receives what was adjusted.
RETROAA_API Status applyFsoFlag(Config& config, const std::string& flag, const std::string& value,
                                std::vector<std::string>& warnings);
// A method as reports, the command line and engines' own options name it:
// `method[/weighting][+stacked]...[@key=value]...`, e.g. `off`, `resolve/fso`, `resolve+fxaa`,
// `adaptive@adaptive_shading_scale=4`: applies the method, the resolve weighting, each stacked post
// filter (the registry's rows with a stack key) and each setting to `config`. Errors are InvalidConfig
// naming the spec and the bad part; `config` may then hold the parts applied before it.
RETROAA_API Status applyMethodSpec(Config& config, const std::string& spec);
// Checks every field of a config built in code with the rules the text parser applies to the same key
// (ranges, allowed values, known enum values). Errors are InvalidConfig naming the key and value.
// Plugin::create and reconfigure call it.
RETROAA_API Status validateConfig(const Config& config);
// Writes a config back as `key=value` lines that applyConfigText reads.
RETROAA_API std::string toConfigText(const Config& config);

}  // namespace retroaa
