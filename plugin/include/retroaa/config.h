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

// Every field is a config key (configKeys(), docs/config.md): the comments here say what a field means;
// its key, allowed values and one-line effect are written once where its technique lives (each method's
// file under plugin/src/methods/ declares its own keys; plugin/src/config.cpp the shared ones), and its
// default is the initialiser below.
struct Config {
  // Which method runs. Changing it reallocates only what the new method needs.
  Method method = Method::Off;
  // MSAA samples of the G-buffer for multi-sample methods. Clamped to the
  // context's GL_MAX_SAMPLES with a warning naming both counts. Changing it reallocates.
  int samples = 4;
  // The G-buffer's source: 0 multisampled (`samples`); m = 2, 3 or 4 supersampled — an m·W × m·H
  // G-buffer, each pixel's m×m window of sub-positions lit like samples (Holländer et al. 2013). The
  // host's model pass then renders at Plugin::geometryScale() × its viewport. Changing it reallocates.
  int supersample = 0;
  // The fraction of each pixel's samples the host's model pass shades where it draws multisampled
  // (Plugin::sampleShading: glMinSampleShading around the model pass). 0: once per pixel, the MSAA
  // default; 1: once per sample, so the host's `discard` (alpha-tested foliage, fences, grates) decides
  // each sample and cut-out edges are anti-aliased like silhouettes, at up to `samples` times the model
  // pass's fragment work. Free to change every frame.
  float sampleShading = 0.0f;
  // How `resolve` weights a pixel's samples. Free to change every frame.
  ResolveWeighting resolveWeighting = ResolveWeighting::Median;
  // Run the resolve (every MSAA method's) as a compute pass: the host's attachments through image stores,
  // its depth through a one-fetch full-screen pass (a depth buffer takes no image stores). The same
  // G-buffer. For GPUs whose pixel shaders run on a small graphics partition (NVIDIA's H100). Where an
  // attachment's format takes no image stores (three-channel, sRGB), the full-screen pass, with a warning.
  bool resolveCompute = false;
  // c of Eq. 1: samples within min(d1,d2)·tan(hfov/width)·c of the reference depth count as one
  // surface. 0 keeps only the reference sample's depth, larger merges more (and,
  // past ~20, blends across real depth steps). Free to change every frame.
  float closeness = 5.0f;
  // Edge detector of `edge`. Free to change every frame (recompiles one small shader).
  EdgeDetector edgeDetector = EdgeDetector::Coverage;
  // c of the `depth` detector: smaller marks more pixels (slower, closer to per-sample).
  float edgeDepthCloseness = 1.0f;
  // Angle of the `normal` detector in degrees: smaller marks more pixels.
  float edgeNormalAngleDegrees = 25.0f;
  // `adaptive` (Holländer et al. 2013): k = clamp(max(k_d, k_n, k_s, k_t), adaptive_min_samples, N).
  // Each scale multiplies its metric; larger refines more pixels (slower, closer to per-sample).
  float adaptiveDepthScale = 0.5f;       // k_d = scale · variance of depth in pixel footprints
  float adaptiveNormalScale = 8.0f;      // k_n = scale · sqrt(1 − min |n̄·n_i|)
  float adaptiveShadingScale = 2.0f;     // k_s = scale · N · luma range of the first lit sample
  float adaptiveTextureScale = 16.0f;    // k_t = scale · N · that range scaled by the albedo's over the pixel
  float adaptiveThresholdMin = 0.0312f;  // k_s = 0 below this luma range (FXAA's)
  float adaptiveThresholdEdge = 0.125f;  // … or below this fraction of the local max luma
  int adaptiveMinSamples = 1;            // floor of k; N forces every sample (equals per-sample)
  // `aggregate` (Crassin et al. 2016): at most c aggregates per pixel (plus one for background).
  int aggregateCount = 2;           // c; more aggregates: closer to per-sample, more evaluations
  float aggregateThreshold = 0.1f;  // t: a new aggregate only beyond this distance; 0 splits all distinct samples
  float aggregateLength = 4.0f;     // k in pixel footprints: depth gaps beyond ~k·sqrt(t) split
  // The coverage filter after tonemapping, stacked on `resolve` (which supplies its MSAA depth, so no
  // prepass): intra-model smoothing plus silhouette blending at one lighting evaluation per pixel.
  bool coverageFilter = false;
  // c of the coverage filter's depth test (Eq. 1 style): a sample whose depth differs from
  // the pixel's by more than min(d)·tan(hfov/width)·c lies across an edge. Smaller finds more (and,
  // on grazing surfaces, false) edges.
  float coverageTolerance = 2.0f;
  // Sub-pixel reconstruction stacked on a G-buffer method (`resolve+reconstruct`: its MSAA depth and
  // normals feed it, so no prepass).
  bool reconstructFilter = false;
  // c of the reconstruction's depth test (Eq. 1 style): a sub-sample belongs to a shaded pixel
  // whose depth is within min(d)·tan(hfov/width)·c of its own (and whose normal agrees).
  float reconstructTolerance = 2.0f;
  // How far, in rings of pixels around its own, a sub-sample that no neighbour matches searches for a
  // shaded pixel on its surface. 1 is the 3×3 neighbourhood of the SRAA paper; a wire thinner
  // than a pixel is hit by a pixel centre only every few pixels along it, so larger radii rebuild it.
  // The search costs only at such sub-samples.
  int reconstructSearchRadius = 6;
  // Reconstruct on the host's HDR light target between lighting and tonemapping (radiance mixes as the
  // ground truth's supersamples do; +8 B/px for a copy) instead of on the display after tonemapping.
  bool reconstructBeforeTonemap = false;
  // Run the reconstruction as a compute pass: each 8×8 tile lists its pixels that need rebuilding, then
  // its invocations search for them one each, on adjacent lanes, instead of a full-screen pass where
  // every searching pixel holds up its neighbours' lanes. The same image. Where the target's format
  // takes no image stores (a three-channel or sRGB target), the full-screen pass, with a warning.
  bool reconstructCompute = false;
  // Temporal accumulation stacked on another method (`resolve+temporal`, `reconstruct+temporal`): the
  // host jitters its projection by Plugin::jitter() and the plugin blends each frame into a history.
  bool temporalFilter = false;
  // The weight of the current frame in the history: smaller converges to a smoother image
  // over more frames (≈ 2/weight) and ghosts longer; 1 keeps no history. Free to change every frame.
  float temporalBlend = 0.1f;
  // Frames in the jitter sequence (Halton 2, 3): the sub-pixel positions a static pixel is
  // sampled at. 1: no jitter (history only smooths flicker). Changing it resets the history.
  int temporalJitterLength = 8;
  // The mip bias the host adds to its material samplers (Plugin::textureLodBias): the history
  // averages the sharper mips' detail over the jitter. FSR 2 advises -1 at native resolution.
  float temporalLodBias = -1.0f;
  // Accumulate on the host's HDR light target between lighting and tonemapping (radiance, as the ground
  // truth averages; 0.5 dB closer to it than after tonemapping on the demo frame) rather than on the
  // display. Where the layout has no single float light target (several light outputs, lighting
  // straight into the display), after tonemapping with a warning. Resets the history.
  bool temporalBeforeTonemap = true;
  // After a slice method's shade(), resolve the MSAA G-buffer into the host's G-buffer again, so passes
  // after lighting that read it (SSAO, fog, debug views) see the resolved surface, not the last slice's
  // samples. Off saves one resolve pass per frame where nothing reads the G-buffer after lighting.
  bool restoreGBufferAfterShade = true;
  // A GPU-time budget for the plugin's passes in ms; 0 is off. With `adaptive` (or `edge`
  // with the depth detector) a damped controller scales the refinement frame to frame to stay near it;
  // it times the passes itself (timer queries). Free to change every frame.
  float budgetMs = 0.0f;
  // FXAA after tonemapping, stacked on any method (FreeSpace Open users combine -msaa and FXAA).
  bool fxaa = false;
  FxaaQuality fxaaQuality = FxaaQuality::High;
  // FXAA edge threshold relative to local contrast; lower finds more edges.
  float fxaaEdgeThreshold = 0.125f;
  // SMAA 1x after tonemapping, stacked on any lighting-stage method (`resolve+smaa`, `edge+smaa`).
  bool smaa = false;
  // Preset of `smaa`, `+smaa` and `smaa-s2x` (FreeSpace Open's -aa_preset 3..6 are low..ultra).
  SmaaQuality smaaQuality = SmaaQuality::High;
  SmaaEdgeDetection smaaEdgeDetection = SmaaEdgeDetection::Luma;
  // A folder whose files replace the built-in shaders of the same relative path (for modders);
  // a file that does not compile falls back to the built-in one with a warning naming file and line.
  std::string shaderOverrideDirectory;
  // Wrap every plugin pass in timer and pipeline-statistics queries, read back frames later without
  // waiting (Plugin::stats(); Plugin::waitForStats() waits): for benchmarks and the viewer overlay.
  bool measureGpuTime = false;
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
  float minimum, maximum;   // Number and Integer
  const char* method = "";  // the method whose registry row declares it; "" for keys every method shares
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
