// The config key table: the keys every method shares and each technique's, from its registry row
// (TechniqueRow::keys), in one list that parses, prints, checks and documents them (configKeys(),
// docs/config.md, the viewer's widgets).
#include "config_keys.h"
#include "technique.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace retroaa {

namespace presets {
const std::map<std::string, std::string>& embeddedFiles();  // generated from presets/*.cfg
}

namespace {

Key methodKey() {
  std::vector<std::pair<int, std::string>> values;
  for (const MethodInfo& row : methodTable()) values.emplace_back(int(row.method), row.name);
  return enumKey(
      "method", std::move(values), [](const Config& c) { return int(c.method); },
      [](Config& c, int value) { c.method = Method(value); },
      "which AA method runs; changing it reallocates only what it needs");
}

// A bundle of other keys (presets/*.cfg, embedded), applied in place; it reads back as "none".
Key presetKey() {
  Key key = choiceOfNames("preset", {"none", "low", "medium", "high", "ultra"},
                          "a bundle of the keys above, tuned by `make presets` (docs/tune.md#presets); keys after it "
                          "override");
  key.parse = [allowed = key.allowedText](Config& c, const std::string& v) -> Status {
    if (v == "none") return Status::ok();
    const auto& files = presets::embeddedFiles();
    const auto found = files.find(v + ".cfg");
    if (found == files.end())
      return invalidConfig("config key 'preset': unknown value " + quotedInput(v) + " (allowed: " + allowed + ")");
    // Quality keys only: where shaders come from and whether to time them stay the user's.
    std::string lines;
    std::istringstream in(found->second);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("shader_override_dir", 0) != 0 && line.rfind("measure_gpu_time", 0) != 0 &&
          line.rfind("measure_pass_floors", 0) != 0 && line.rfind("preset", 0) != 0)
        lines += line + "\n";
    return applyConfigText(c, lines, "preset " + v);
  };
  key.print = [](const Config&) { return std::string("none"); };
  key.check = [](const Config&) { return Status::ok(); };
  return key;
}

// The keys every method shares, then each technique's (registry order, TechniqueRow::keys), then the
// shared keys that act on all of them.
std::vector<Key> buildKeys() {
  std::vector<Key> keys;
  keys.push_back(methodKey());
  keys.push_back(choice("samples", &Config::samples, {1, 2, 4, 8, 16},
                        "MSAA samples of multi-sample methods; clamped to GL_MAX_SAMPLES with a warning; reallocates"));
  keys.push_back(
      number("sample_shading", &Config::sampleShading, 0, 1,
             "fraction of samples the host's model pass shades where it draws multisampled (glMinSampleShading): 1 "
             "runs its discard per sample, anti-aliasing cut-out edges, at up to samples x the model pass's cost"));
  keys.push_back(number("cutout_sample_shading", &Config::cutOutSampleShading, 0, 1,
                        "the same for the model pass's cut-out draws alone (their fragment shader discards: foliage, "
                        "fences), where the host tells them apart (Plugin::cutOutDrawSettings): 1 anti-aliases cut-out "
                        "edges for the cost of those draws; at least sample_shading"));
  for (const TechniqueRow& row : techniqueRegistry())
    if (row.keys)
      for (Key& key : row.keys()) {
        key.info.methods = {row.info.name};
        keys.push_back(std::move(key));
      }
  keys.push_back(
      onOff("restore_gbuffer_after_shade", &Config::restoreGBufferAfterShade,
            "after a slice method's lighting, resolve into your G-buffer again so later passes read the resolved "
            "surface, not the last slice; off saves one resolve pass"));
  keys.push_back(onOff("slice_tiles", &Config::sliceTiles,
                       "a slice method's passes limited to the pixels lit more than once draw only the 16x16 tiles "
                       "that hold them (listed on the GPU each frame); off draws full screens the stencil limits, "
                       "the same image"));
  keys.push_back(presetKey());
  keys.push_back(
      number("budget_ms", &Config::budgetMs, 0, 1000,
             "GPU budget of the plugin's passes; the methods that refine per pixel scale their refinement frame to "
             "frame to keep it; 0 is off"));
  keys.push_back(folder("shader_override_dir", &Config::shaderOverrideDirectory,
                        "files there replace built-in shaders of the same path; compile errors fall back"));
  keys.push_back(
      onOff("measure_gpu_time", &Config::measureGpuTime,
            "timer and fragment-invocation queries per plugin pass, read back frames later (stats() never waits; "
            "waitForStats() does)"));
  keys.push_back(
      onOff("measure_pass_floors", &Config::measurePassFloors,
            "with measure_gpu_time: after each plugin pass, a pass of the same shape that only fetches and writes the "
            "same bytes, timed as <pass>.floor (its floor on this device; adds that GPU work to the frame)"));
  for (const TechniqueRow& row : techniqueRegistry())  // the keys a method reads besides its own
    for (const char* name : row.otherKeys) {
      auto key =
          std::find_if(keys.begin(), keys.end(), [name](const Key& k) { return k.info.name == std::string(name); });
      if (key == keys.end()) {  // a registry row naming no key: a programming error, found by every test
        std::fprintf(stderr, "retroaa: the registry row '%s' reads a config key '%s' that no one declares\n",
                     row.info.name, name);
        std::abort();
      }
      key->info.methods.push_back(row.info.name);
    }
  const Config defaults;
  for (Key& key : keys) {  // the strings now have their final homes
    key.defaultText = key.print(defaults);
    key.info.defaultValue = key.defaultText.c_str();
    key.info.allowed = key.allowedText.c_str();
  }
  return keys;
}

const std::vector<Key>& keys() {
  static const std::vector<Key> table = buildKeys();
  return table;
}

const Key* findKey(const std::string& name) {
  for (const Key& key : keys())
    if (name == key.info.name) return &key;
  return nullptr;
}

}  // namespace

const std::vector<ConfigKey>& configKeys() {
  static const std::vector<ConfigKey> infos = [] {
    std::vector<ConfigKey> out;
    for (const Key& key : keys()) out.push_back(key.info);
    return out;
  }();
  return infos;
}

std::string readSetting(const Config& config, const std::string& name) {
  const Key* key = findKey(name);
  return key ? key->print(config) : "";
}

std::vector<std::string> settingValues(const std::string& name) {
  const Key* key = findKey(name);
  return key ? key->values : std::vector<std::string>{};
}

Status applySetting(Config& config, const std::string& key, const std::string& value) {
  if (const Key* found = findKey(key)) return found->parse(config, trimmed(value));
  std::string known;
  for (const Key& k : keys()) known += std::string(known.empty() ? "" : ", ") + k.info.name;
  return invalidConfig("unknown config key " + quotedInput(key) + " (known keys: " + known + ")");
}

Status validateConfig(const Config& config) {
  for (const Key& key : keys())
    if (Status status = key.check(config); !status) return status;
  return Status::ok();
}

std::string toConfigText(const Config& config) {
  std::string out;
  for (const Key& key : keys()) out += std::string(key.info.name) + "=" + key.print(config) + "\n";
  return out;
}

}  // namespace retroaa
