#include "retroaa/config.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace retroaa {

namespace presets {
const std::map<std::string, std::string>& embeddedFiles();  // generated from presets/*.cfg
}

namespace {

Error invalid(const std::string& message) { return Error{ErrorCode::InvalidConfig, message}; }

// User input as a message quotes it: at most 80 characters, control and non-ASCII bytes as \xNN, so a
// 10 MB line or a binary file cannot flood or garble a terminal.
std::string quoted(const std::string& text) {
  constexpr size_t kMost = 80;
  std::string out = "'";
  for (size_t i = 0; i < text.size() && i < kMost; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += char(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
  }
  out += "'";
  if (text.size() > kMost)
    out += " (" + std::to_string(text.size()) + " bytes, first " + std::to_string(kMost) + " shown)";
  return out;
}

std::string trim(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

// One name table per enum: toString, the parser and each key's allowed list read it.
template <typename Enum>
struct Named {
  Enum value;
  const char* name;
};
constexpr Named<EdgeDetector> kEdgeDetectors[] = {
    {EdgeDetector::Depth, "depth"},       {EdgeDetector::Plane, "plane"},
    {EdgeDetector::Normal, "normal"},     {EdgeDetector::Material, "material"},
    {EdgeDetector::Coverage, "coverage"}, {EdgeDetector::EveryPixel, "every_pixel"}};
constexpr Named<ResolveWeighting> kWeightings[] = {
    {ResolveWeighting::Median, "median"}, {ResolveWeighting::Front, "front"}, {ResolveWeighting::Back, "back"},
    {ResolveWeighting::Fso, "fso"},       {ResolveWeighting::Mean, "mean"},   {ResolveWeighting::Window, "window"}};
constexpr Named<FxaaQuality> kFxaaQualities[] = {
    {FxaaQuality::Low, "low"}, {FxaaQuality::Medium, "medium"}, {FxaaQuality::High, "high"}};
constexpr Named<SmaaQuality> kSmaaQualities[] = {{SmaaQuality::Low, "low"},
                                                 {SmaaQuality::Medium, "medium"},
                                                 {SmaaQuality::High, "high"},
                                                 {SmaaQuality::Ultra, "ultra"}};
constexpr Named<SmaaEdgeDetection> kSmaaEdgeDetections[] = {
    {SmaaEdgeDetection::Luma, "luma"}, {SmaaEdgeDetection::Colour, "colour"}, {SmaaEdgeDetection::Depth, "depth"}};

template <typename Enum, size_t N>
const char* nameIn(const Named<Enum> (&table)[N], Enum value) {
  for (const Named<Enum>& row : table)
    if (row.value == value) return row.name;
  return "?";
}

// "a, b, c": a key's allowed values, built once per table.
template <typename Enum, size_t N>
const char* namesOf(const Named<Enum> (&table)[N]) {
  static const std::string names = [&table] {
    std::string list;
    for (const Named<Enum>& row : table) list += std::string(list.empty() ? "" : ", ") + row.name;
    return list;
  }();
  return names.c_str();
}

template <typename Enum, size_t N>
Status parseEnum(const std::string& key, const std::string& value, const Named<Enum> (&table)[N], Enum& out) {
  for (const Named<Enum>& row : table)
    if (value == row.name) {
      out = row.value;
      return Status::ok();
    }
  return invalid("config key '" + key + "': unknown value " + quoted(value) + " (allowed: " + namesOf(table) + ")");
}

Status parseFloat(const std::string& key, const std::string& value, float minimum, float maximum, float& out) {
  char* end = nullptr;
  const double parsed = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(parsed) || parsed < minimum ||
      parsed > maximum) {
    std::ostringstream message;
    message << "config key '" << key << "': value " << quoted(value) << " is not a number in [" << minimum << ", "
            << maximum << "]";
    return invalid(message.str());
  }
  out = static_cast<float>(parsed);
  return Status::ok();
}

Status parseInt(const std::string& key, const std::string& value, int minimum, int maximum, int& out) {
  float parsed = 0;
  const Status number = parseFloat(key, value, float(minimum), float(maximum), parsed);
  if (!number || parsed != std::floor(parsed))
    return invalid("config key '" + key + "': value " + quoted(value) + " is not an integer in [" +
                   std::to_string(minimum) + ", " + std::to_string(maximum) + "]");
  out = int(parsed);
  return Status::ok();
}

Status parseBool(const std::string& key, const std::string& value, bool& out) {
  if (value == "on" || value == "true" || value == "1") return out = true, Status::ok();
  if (value == "off" || value == "false" || value == "0") return out = false, Status::ok();
  return invalid("config key '" + key + "': value " + quoted(value) + " is not a switch (allowed: on, off)");
}

Status parseMethod(const std::string& value, Method& out) {
  std::string allowed;
  for (const MethodInfo& row : methodTable()) {
    if (value == row.name) return out = row.method, Status::ok();
    allowed += std::string(allowed.empty() ? "" : ", ") + row.name;
  }
  return invalid("config key 'method': unknown value " + quoted(value) + " (allowed: " + allowed + ")");
}

const char* methodNames() {
  static const std::string names = [] {
    std::string list;
    for (const MethodInfo& row : methodTable()) list += std::string(list.empty() ? "" : ", ") + row.name;
    return list;
  }();
  return names.c_str();
}
struct Setter {
  ConfigKey key;
  Status (*apply)(Config&, const std::string& value);
  std::string (*read)(const Config&);
};

// Digits of floats written back: 6 for config text people read; validateConfig raises it so that no
// out-of-range value rounds into range.
thread_local int floatDigits = 6;

std::string formatFloat(float v) {
  std::ostringstream out;
  out << std::setprecision(floatDigits) << v;
  return out.str();
}

const std::vector<Setter>& setters() {
  static const std::vector<Setter> table = {
      {{"method", "off", methodNames(), "which AA method runs; changing it reallocates only what it needs"},
       [](Config& c, const std::string& v) { return parseMethod(v, c.method); },
       [](const Config& c) { return std::string(toString(c.method)); }},
      {{"samples", "4", "1, 2, 4, 8, 16",
        "MSAA samples of multi-sample methods; clamped to GL_MAX_SAMPLES with a warning; reallocates"},
       [](Config& c, const std::string& v) -> Status {
         for (int allowed : {1, 2, 4, 8, 16})
           if (v == std::to_string(allowed)) return c.samples = allowed, Status::ok();
         return invalid("config key 'samples': unsupported sample count " + quoted(v) + " (allowed: 1, 2, 4, 8, 16)");
       },
       [](const Config& c) { return std::to_string(c.samples); }},
      {{"supersample", "0", "0, 2, 3, 4",
        "G-buffer methods' source: 0 multisampled (samples); m an m x m supersampled G-buffer (the host's model "
        "pass renders at m x its viewport, Plugin::geometryScale), its m^2 sub-positions lit like samples; "
        "reallocates"},
       [](Config& c, const std::string& v) -> Status {
         for (int allowed : {0, 2, 3, 4})
           if (v == std::to_string(allowed)) return c.supersample = allowed, Status::ok();
         return invalid("config key 'supersample': unsupported factor " + quoted(v) + " (allowed: 0, 2, 3, 4)");
       },
       [](const Config& c) { return std::to_string(c.supersample); }},
      {{"resolve_weighting", "median", namesOf(kWeightings), "how resolve weights a pixel's samples; free per frame"},
       [](Config& c, const std::string& v) {
         return parseEnum("resolve_weighting", v, kWeightings, c.resolveWeighting);
       },
       [](const Config& c) { return std::string(toString(c.resolveWeighting)); }},
      {{"resolve_compute", "off", "on, off",
        "the resolve as a compute pass, the depth through a one-fetch full-screen pass (the same G-buffer; for "
        "GPUs whose pixel shaders run on a small partition; where an attachment's format takes no image stores, "
        "the full-screen pass with a warning)"},
       [](Config& c, const std::string& v) { return parseBool("resolve_compute", v, c.resolveCompute); },
       [](const Config& c) { return std::string(c.resolveCompute ? "on" : "off"); }},
      {{"closeness", "5", "0 .. 100",
        "c of Eq. 1; larger merges more samples into one surface (past ~20 it blends across depth steps)"},
       [](Config& c, const std::string& v) { return parseFloat("closeness", v, 0.0f, 100.0f, c.closeness); },
       [](const Config& c) { return formatFloat(c.closeness); }},
      {{"edge_detector", "coverage", namesOf(kEdgeDetectors),
        "how `edge` finds pixels to light per sample; free per frame"},
       [](Config& c, const std::string& v) { return parseEnum("edge_detector", v, kEdgeDetectors, c.edgeDetector); },
       [](const Config& c) { return std::string(toString(c.edgeDetector)); }},
      {{"edge_depth_closeness", "1", "0 .. 100",
        "c of the depth detector; smaller marks more pixels (slower, closer to per-sample)"},
       [](Config& c, const std::string& v) {
         return parseFloat("edge_depth_closeness", v, 0.0f, 100.0f, c.edgeDepthCloseness);
       },
       [](const Config& c) { return formatFloat(c.edgeDepthCloseness); }},
      {{"edge_normal_angle_deg", "25", "0 .. 180", "angle of the normal detector; smaller marks more pixels"},
       [](Config& c, const std::string& v) {
         return parseFloat("edge_normal_angle_deg", v, 0.0f, 180.0f, c.edgeNormalAngleDegrees);
       },
       [](const Config& c) { return formatFloat(c.edgeNormalAngleDegrees); }},
      {{"adaptive_depth_scale", "0.5", "0 .. 1000",
        "adaptive: k_d per unit of depth variance (in pixel footprints²); larger refines more"},
       [](Config& c, const std::string& v) {
         return parseFloat("adaptive_depth_scale", v, 0.0f, 1000.0f, c.adaptiveDepthScale);
       },
       [](const Config& c) { return formatFloat(c.adaptiveDepthScale); }},
      {{"adaptive_normal_scale", "8", "0 .. 1000",
        "adaptive: k_n per unit of normal-cone width sqrt(1 - min|n·n_i|); larger refines more"},
       [](Config& c, const std::string& v) {
         return parseFloat("adaptive_normal_scale", v, 0.0f, 1000.0f, c.adaptiveNormalScale);
       },
       [](const Config& c) { return formatFloat(c.adaptiveNormalScale); }},
      {{"adaptive_shading_scale", "2", "0 .. 1000",
        "adaptive: k_s = scale * N * luma range of the first lit sample; larger refines more"},
       [](Config& c, const std::string& v) {
         return parseFloat("adaptive_shading_scale", v, 0.0f, 1000.0f, c.adaptiveShadingScale);
       },
       [](const Config& c) { return formatFloat(c.adaptiveShadingScale); }},
      {{"adaptive_texture_scale", "16", "0 .. 1000",
        "adaptive: k_t = scale * N * luma range of the first lit sample scaled by the albedo over the pixel "
        "(texture detail inside it); larger refines more"},
       [](Config& c, const std::string& v) {
         return parseFloat("adaptive_texture_scale", v, 0.0f, 1000.0f, c.adaptiveTextureScale);
       },
       [](const Config& c) { return formatFloat(c.adaptiveTextureScale); }},
      {{"adaptive_threshold_min", "0.0312", "0 .. 1",
        "adaptive: luma ranges below this never refine (FXAA's absolute threshold)"},
       [](Config& c, const std::string& v) {
         return parseFloat("adaptive_threshold_min", v, 0.0f, 1.0f, c.adaptiveThresholdMin);
       },
       [](const Config& c) { return formatFloat(c.adaptiveThresholdMin); }},
      {{"adaptive_threshold_edge", "0.125", "0 .. 1",
        "adaptive: luma ranges below this fraction of the local maximum never refine"},
       [](Config& c, const std::string& v) {
         return parseFloat("adaptive_threshold_edge", v, 0.0f, 1.0f, c.adaptiveThresholdEdge);
       },
       [](const Config& c) { return formatFloat(c.adaptiveThresholdEdge); }},
      {{"adaptive_min_samples", "1", "1 .. 16", "adaptive: floor of the per-pixel sample count; N lights every sample"},
       [](Config& c, const std::string& v) { return parseInt("adaptive_min_samples", v, 1, 16, c.adaptiveMinSamples); },
       [](const Config& c) { return std::to_string(c.adaptiveMinSamples); }},
      {{"aggregate_count", "2", "1 .. 4",
        "aggregate: at most this many aggregates per pixel (plus background); more is closer to per-sample"},
       [](Config& c, const std::string& v) -> Status {
         for (int allowed : {1, 2, 3, 4})
           if (v == std::to_string(allowed)) return c.aggregateCount = allowed, Status::ok();
         return invalid("config key 'aggregate_count': value " + quoted(v) + " is not one of 1, 2, 3, 4");
       },
       [](const Config& c) { return std::to_string(c.aggregateCount); }},
      {{"aggregate_threshold", "0.1", "0 .. 10",
        "aggregate: t, the distance beyond which a sample seeds a new aggregate; 0 splits every distinct sample"},
       [](Config& c, const std::string& v) {
         return parseFloat("aggregate_threshold", v, 0.0f, 10.0f, c.aggregateThreshold);
       },
       [](const Config& c) { return formatFloat(c.aggregateThreshold); }},
      {{"aggregate_length", "4", "0.01 .. 1000",
        "aggregate: k, the characteristic length in pixel footprints; smaller splits at smaller depth gaps"},
       [](Config& c, const std::string& v) {
         return parseFloat("aggregate_length", v, 0.01f, 1000.0f, c.aggregateLength);
       },
       [](const Config& c) { return formatFloat(c.aggregateLength); }},
      {{"coverage_filter", "off", "on, off",
        "the coverage filter on top of resolve (reuses its MSAA depth; no prepass)"},
       [](Config& c, const std::string& v) { return parseBool("coverage_filter", v, c.coverageFilter); },
       [](const Config& c) { return std::string(c.coverageFilter ? "on" : "off"); }},
      {{"coverage_tolerance", "2", "0 .. 100",
        "coverage: c of the depth test; smaller finds more edges, false ones on grazing surfaces"},
       [](Config& c, const std::string& v) {
         return parseFloat("coverage_tolerance", v, 0.0f, 100.0f, c.coverageTolerance);
       },
       [](const Config& c) { return formatFloat(c.coverageTolerance); }},
      {{"reconstruct_filter", "off", "on, off",
        "sub-pixel reconstruction on top of resolve (reuses its MSAA depth and normals; no prepass)"},
       [](Config& c, const std::string& v) { return parseBool("reconstruct_filter", v, c.reconstructFilter); },
       [](const Config& c) { return std::string(c.reconstructFilter ? "on" : "off"); }},
      {{"reconstruct_tolerance", "2", "0 .. 100",
        "reconstruct: c of the depth test that ties a sub-sample to a shaded pixel"},
       [](Config& c, const std::string& v) {
         return parseFloat("reconstruct_tolerance", v, 0.0f, 100.0f, c.reconstructTolerance);
       },
       [](const Config& c) { return formatFloat(c.reconstructTolerance); }},
      {{"reconstruct_search_radius", "6", "1 .. 8",
        "reconstruct: how many rings of pixels a sub-sample searches for its surface when no neighbour holds it "
        "(sub-pixel wires: a pixel centre on the same wire lies a few pixels along it)"},
       [](Config& c, const std::string& v) {
         return parseInt("reconstruct_search_radius", v, 1, 8, c.reconstructSearchRadius);
       },
       [](const Config& c) { return std::to_string(c.reconstructSearchRadius); }},
      {{"reconstruct_before_tonemap", "off", "on, off",
        "reconstruct on the HDR light target before tonemapping (+8 B/px) instead of on the display"},
       [](Config& c, const std::string& v) {
         return parseBool("reconstruct_before_tonemap", v, c.reconstructBeforeTonemap);
       },
       [](const Config& c) { return std::string(c.reconstructBeforeTonemap ? "on" : "off"); }},
      {{"reconstruct_compute", "off", "on, off",
        "reconstruct as a compute pass that packs each 8x8 tile's searching pixels onto adjacent invocations "
        "instead of a full-screen pass (the same image; where the target's format takes no image stores, the "
        "full-screen pass with a warning)"},
       [](Config& c, const std::string& v) { return parseBool("reconstruct_compute", v, c.reconstructCompute); },
       [](const Config& c) { return std::string(c.reconstructCompute ? "on" : "off"); }},
      {{"temporal_filter", "off", "on, off",
        "temporal accumulation on top of another method (resolve+temporal, reconstruct+temporal): the host "
        "jitters its projection by Plugin::jitter()"},
       [](Config& c, const std::string& v) { return parseBool("temporal_filter", v, c.temporalFilter); },
       [](const Config& c) { return std::string(c.temporalFilter ? "on" : "off"); }},
      {{"temporal_blend", "0.1", "0.02 .. 1",
        "temporal: the current frame's weight in the history; smaller is smoother and converges over more frames "
        "(about 2/weight), ghosting longer; 1 keeps no history; free per frame"},
       [](Config& c, const std::string& v) { return parseFloat("temporal_blend", v, 0.02f, 1.0f, c.temporalBlend); },
       [](const Config& c) { return formatFloat(c.temporalBlend); }},
      {{"temporal_jitter_length", "8", "1 .. 64",
        "temporal: frames in the Halton (2, 3) jitter sequence, the sub-pixel positions a still pixel is sampled at; "
        "1 is no jitter; resets the history"},
       [](Config& c, const std::string& v) {
         return parseInt("temporal_jitter_length", v, 1, 64, c.temporalJitterLength);
       },
       [](const Config& c) { return std::to_string(c.temporalJitterLength); }},
      {{"temporal_lod_bias", "-1", "-3 .. 0",
        "temporal: the mip bias the host adds to its material samplers (Plugin::textureLodBias): sharper mips whose "
        "detail the history averages over the jitter; FSR 2 advises -1 at native resolution"},
       [](Config& c, const std::string& v) {
         return parseFloat("temporal_lod_bias", v, -3.0f, 0.0f, c.temporalLodBias);
       },
       [](const Config& c) { return formatFloat(c.temporalLodBias); }},
      {{"temporal_before_tonemap", "on", "on, off",
        "temporal on the HDR light target before tonemapping (radiance, as the ground truth averages) rather than on "
        "the display (where the layout has no single float light target, after tonemapping with a warning); resets "
        "the history"},
       [](Config& c, const std::string& v) { return parseBool("temporal_before_tonemap", v, c.temporalBeforeTonemap); },
       [](const Config& c) { return std::string(c.temporalBeforeTonemap ? "on" : "off"); }},
      {{"restore_gbuffer_after_shade", "on", "on, off",
        "after a slice method's lighting, resolve into your G-buffer again so later passes read the resolved "
        "surface, not the last slice; off saves one resolve pass"},
       [](Config& c, const std::string& v) {
         return parseBool("restore_gbuffer_after_shade", v, c.restoreGBufferAfterShade);
       },
       [](const Config& c) { return std::string(c.restoreGBufferAfterShade ? "on" : "off"); }},
      {{"preset", "none", "none, low, medium, high, ultra",
        "a bundle of the keys above, tuned by `make presets` (docs/tune.md#presets); keys after it override"},
       [](Config& c, const std::string& v) -> Status {
         if (v == "none") return Status::ok();
         const auto& files = presets::embeddedFiles();
         const auto found = files.find(v + ".cfg");
         if (found == files.end())
           return invalid("config key 'preset': unknown value " + quoted(v) +
                          " (allowed: none, low, medium, high, ultra)");
         // Quality keys only: where shaders come from and whether to time them stay the user's.
         std::string lines;
         std::istringstream in(found->second);
         for (std::string line; std::getline(in, line);)
           if (line.rfind("shader_override_dir", 0) != 0 && line.rfind("measure_gpu_time", 0) != 0 &&
               line.rfind("preset", 0) != 0)
             lines += line + "\n";
         return applyConfigText(c, lines, "preset " + v);
       },
       [](const Config&) { return std::string("none"); }},
      {{"budget_ms", "0", "0 .. 1000",
        "GPU budget of the plugin's passes; adaptive (and edge/depth) adjust their refinement frame to frame to keep "
        "it; 0 is off"},
       [](Config& c, const std::string& v) { return parseFloat("budget_ms", v, 0.0f, 1000.0f, c.budgetMs); },
       [](const Config& c) { return formatFloat(c.budgetMs); }},
      {{"fxaa", "off", "on, off", "FXAA after tonemapping, stacked on the method"},
       [](Config& c, const std::string& v) { return parseBool("fxaa", v, c.fxaa); },
       [](const Config& c) { return std::string(c.fxaa ? "on" : "off"); }},
      {{"fxaa_quality", "high", namesOf(kFxaaQualities),
        "FXAA edge search length (3, 6, 12 steps); cost grows with it"},
       [](Config& c, const std::string& v) { return parseEnum("fxaa_quality", v, kFxaaQualities, c.fxaaQuality); },
       [](const Config& c) { return std::string(toString(c.fxaaQuality)); }},
      {{"fxaa_edge_threshold", "0.125", "0.063 .. 0.333", "FXAA local contrast needed to filter; lower softens more"},
       [](Config& c, const std::string& v) {
         return parseFloat("fxaa_edge_threshold", v, 0.063f, 0.333f, c.fxaaEdgeThreshold);
       },
       [](const Config& c) { return formatFloat(c.fxaaEdgeThreshold); }},
      {{"smaa", "off", "on, off", "SMAA 1x after tonemapping, stacked on the method (before +fxaa)"},
       [](Config& c, const std::string& v) { return parseBool("smaa", v, c.smaa); },
       [](const Config& c) { return std::string(c.smaa ? "on" : "off"); }},
      {{"smaa_quality", "high", namesOf(kSmaaQualities),
        "SMAA preset: threshold 0.15/0.1/0.1/0.05, search 8/16/32/64 px each way, diagonals and corner rounding "
        "from high on; cost grows with it (FreeSpace Open's -aa_preset 3..6)"},
       [](Config& c, const std::string& v) { return parseEnum("smaa_quality", v, kSmaaQualities, c.smaaQuality); },
       [](const Config& c) { return std::string(toString(c.smaaQuality)); }},
      {{"smaa_edge_detection", "luma", namesOf(kSmaaEdgeDetections),
        "what SMAA finds edges in: luma contrast, per-channel contrast (chroma edges too), or view-depth steps "
        "(geometry only: keeps texture detail, misses shading edges)"},
       [](Config& c, const std::string& v) {
         return parseEnum("smaa_edge_detection", v, kSmaaEdgeDetections, c.smaaEdgeDetection);
       },
       [](const Config& c) { return std::string(toString(c.smaaEdgeDetection)); }},
      {{"shader_override_dir", "", "a folder",
        "files there replace built-in shaders of the same path; compile errors fall back"},
       [](Config& c, const std::string& v) { return c.shaderOverrideDirectory = v, Status::ok(); },
       [](const Config& c) { return c.shaderOverrideDirectory; }},
      {{"measure_gpu_time", "off", "on, off",
        "timer and fragment-invocation queries per plugin pass, read back frames later (never waits)"},
       [](Config& c, const std::string& v) { return parseBool("measure_gpu_time", v, c.measureGpuTime); },
       [](const Config& c) { return std::string(c.measureGpuTime ? "on" : "off"); }},
  };
  return table;
}

}  // namespace

const char* toString(Method method) {
  const MethodInfo* row = findMethod(method);
  return row ? row->name : "?";
}

const char* toString(ResolveWeighting weighting) { return nameIn(kWeightings, weighting); }
const char* toString(FxaaQuality quality) { return nameIn(kFxaaQualities, quality); }
const char* toString(SmaaQuality quality) { return nameIn(kSmaaQualities, quality); }
const char* toString(SmaaEdgeDetection detection) { return nameIn(kSmaaEdgeDetections, detection); }
const char* toString(EdgeDetector detector) { return nameIn(kEdgeDetectors, detector); }

const std::vector<ConfigKey>& configKeys() {
  static const std::vector<ConfigKey> keys = [] {
    std::vector<ConfigKey> out;
    for (const Setter& s : setters()) out.push_back(s.key);
    return out;
  }();
  return keys;
}

std::string readSetting(const Config& config, const std::string& key) {
  for (const Setter& s : setters())
    if (key == s.key.name) return s.read(config);
  return "";
}

std::vector<std::string> settingValues(const std::string& key) {
  std::vector<std::string> values;
  if (key == "method") {
    for (const MethodInfo& row : methodTable()) values.push_back(row.name);
    return values;
  }
  for (const Setter& s : setters()) {
    if (key != s.key.name) continue;
    const std::string allowed = s.key.allowed;
    if (allowed.find("..") != std::string::npos || allowed.find(' ') == std::string::npos ||
        allowed.find(',') == std::string::npos)
      return values;  // a range or a folder
    std::istringstream in(allowed);
    for (std::string value; std::getline(in, value, ',');) values.push_back(trim(value));
  }
  return values;
}

Status applySetting(Config& config, const std::string& key, const std::string& value) {
  std::string known;
  for (const Setter& s : setters()) {
    if (key == s.key.name) return s.apply(config, trim(value));
    known += std::string(known.empty() ? "" : ", ") + s.key.name;
  }
  return invalid("unknown config key " + quoted(key) + " (known keys: " + known + ")");
}

Status applyConfigText(Config& config, const std::string& text, const std::string& sourceName) {
  Config updated = config;  // a bad line leaves the caller's config untouched
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const size_t equals = content.find('=');
    if (equals == std::string::npos)
      return invalid(sourceName + ":" + std::to_string(number) + ": expected 'key=value', got " + quoted(content));
    const Status status = applySetting(updated, trim(content.substr(0, equals)), content.substr(equals + 1));
    if (!status) return invalid(sourceName + ":" + std::to_string(number) + ": " + status.error().message);
  }
  config = updated;
  return Status::ok();
}

Status applyConfigFile(Config& config, const std::string& path) {
  // A regular file of bounded size: a directory would read as empty, /dev/zero would never end.
  constexpr std::uintmax_t kMaxBytes = 1u << 20;
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) return invalid(path + ": cannot open config file: it does not exist");
  if (std::filesystem::is_directory(status)) return invalid(path + ": cannot open config file: it is a directory");
  if (!std::filesystem::is_regular_file(status))
    return invalid(path + ": cannot open config file: it is not a regular file");
  if (const std::uintmax_t bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxBytes)
    return invalid(path + ": cannot open config file: it is " + std::to_string(bytes) +
                   " bytes, more than the 1 MiB allowed");
  std::ifstream in(path);
  if (!in) return invalid(path + ": cannot open config file");
  std::stringstream text;
  text << in.rdbuf();
  return applyConfigText(config, text.str(), path);
}

Status applySettingsList(Config& config, const std::string& list, const std::string& sourceName) {
  std::string lines = list;
  for (char& c : lines)
    if (c == ',' || c == ';') c = '\n';
  return applyConfigText(config, lines, sourceName);
}

Status applyFsoFlag(Config& config, const std::string& flag, const std::string& value,
                    std::vector<std::string>& warnings) {
  char* end = nullptr;
  const long n = std::strtol(value.c_str(), &end, 10);
  const bool isInteger = !value.empty() && end == value.c_str() + value.size();
  if (flag == "-msaa") {
    if (!isInteger) return invalid("-msaa: value " + quoted(value) + " is not an integer (allowed: 0, 4, 8, 16)");
    if (n != 0 && n != 4 && n != 8 && n != 16) {
      warnings.push_back("-msaa " + (value.size() <= 20 ? value : quoted(value)) +
                         " is not one of 0, 4, 8, 16; using 0 as FreeSpace Open does");
      config.samples = 4;
      if (usesMsaa(config.method)) config.method = Method::Off;
      return Status::ok();
    }
    if (n == 0) {
      if (usesMsaa(config.method)) config.method = Method::Off;
    } else {
      config.samples = static_cast<int>(n);
      if (config.method == Method::Fxaa) config.fxaa = true;          // -aa_preset came first: keep FXAA
      if (config.method == Method::Smaa) config.smaa = true;          // … or SMAA
      if (!usesMsaa(config.method)) config.method = Method::Resolve;  // FSO's MSAA is the resolve
    }
    return Status::ok();
  }
  if (flag == "-aa_preset") {
    if (!isInteger || n < 0 || n > 6)
      return invalid("-aa_preset: value " + quoted(value) + " is not an integer in 0..6");
    // FreeSpace Open's presets: 0..2 FXAA low/medium/high, 3..6 SMAA low/medium/high/ultra.
    const bool smaa = n >= 3;
    if (smaa)
      config.smaaQuality = kSmaaQualities[n - 3].value;
    else
      config.fxaaQuality = kFxaaQualities[n].value;
    const Method post = smaa ? Method::Smaa : Method::Fxaa;
    // The last -aa_preset wins: one post filter, as in FreeSpace Open.
    if (config.method == Method::Off || config.method == Method::Fxaa || config.method == Method::Smaa) {
      config.method = post;
      config.fxaa = config.smaa = false;
    } else {
      config.fxaa = !smaa;
      config.smaa = smaa;
    }
    return Status::ok();
  }
  if (flag == "-post_process_aa") {
    // FreeSpace Open (code/cmdline/cmdline.cpp): post-processing AA on, SMAA low unless -aa_preset names
    // a preset; the preset wins in either order.
    if (config.method == Method::Fxaa || config.method == Method::Smaa || config.fxaa || config.smaa)
      return Status::ok();
    return applyFsoFlag(config, "-aa_preset", "3", warnings);
  }
  return invalid("unknown FreeSpace Open flag " + quoted(flag) + " (known: -msaa, -aa_preset, -post_process_aa)");
}

Status validateConfig(const Config& config) {
  const int digits = floatDigits;
  floatDigits = 9;  // every float exactly enough to round-trip
  Status status = Status::ok();
  for (const Setter& s : setters()) {
    Config scratch;
    status = s.apply(scratch, s.read(config));
    if (!status) break;
  }
  floatDigits = digits;
  return status;
}

std::string toConfigText(const Config& config) {
  std::string out;
  for (const Setter& s : setters()) out += std::string(s.key.name) + "=" + s.read(config) + "\n";
  return out;
}

Status applyMethodSpec(Config& config, const std::string& spec) {
  auto bad = [&spec](const std::string& why) {
    return Error{ErrorCode::InvalidConfig, "method '" + spec + "': " + why};
  };
  std::string rest = spec;
  // Settings after '@' apply to this spec only: adaptive@adaptive_shading_scale=4@adaptive_depth_scale=1
  for (size_t at = rest.rfind('@'); at != std::string::npos; at = rest.rfind('@')) {
    const std::string setting = rest.substr(at + 1);
    const size_t equals = setting.find('=');
    if (equals == std::string::npos) return bad("expected key=value after '@', got '" + setting + "'");
    if (Status status = applySetting(config, setting.substr(0, equals), setting.substr(equals + 1)); !status)
      return bad(status.error().message);
    rest = rest.substr(0, at);
  }
  // Stacked post filters (`+NAME`, in any order): the registry rows with a stack key.
  for (size_t plus = rest.rfind('+'); plus != std::string::npos; plus = rest.rfind('+')) {
    const std::string stacked = rest.substr(plus + 1);
    std::string stackable;
    const MethodInfo* found = nullptr;
    for (const MethodInfo& row : methodTable()) {
      if (!*row.stackKey) continue;
      stackable += std::string(stackable.empty() ? "" : ", ") + "'+" + row.name + "'";
      if (stacked == row.name) found = &row;
    }
    if (!found) return bad("only " + stackable + " can be stacked");
    if (Status status = applySetting(config, found->stackKey, "on"); !status) return bad(status.error().message);
    rest = rest.substr(0, plus);
  }
  const size_t slash = rest.find('/');
  if (slash != std::string::npos) {
    if (Status status = applySetting(config, "resolve_weighting", rest.substr(slash + 1)); !status)
      return bad(status.error().message);
    rest = rest.substr(0, slash);
  }
  if (Status status = applySetting(config, "method", rest); !status) return bad(status.error().message);
  return Status::ok();
}

}  // namespace retroaa
