#include "retroaa/config.h"

#include "config_keys.h"
#include "technique.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
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

template <typename Enum, size_t N>
const char* nameIn(const Named<Enum> (&table)[N], Enum value) {
  for (const Named<Enum>& row : table)
    if (row.value == value) return row.name;
  return "?";
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

std::string formatFloat(float v) {
  std::ostringstream out;
  out << v;  // 6 significant digits: config text people read
  return out.str();
}

template <typename Value>
std::string listed(const std::vector<Value>& values) {
  std::ostringstream out;
  for (size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
  return out.str();
}

Key makeKey(const char* name, ConfigKey::Kind kind, const char* effect) {
  Key key;
  key.info = ConfigKey{name, "", "", effect, kind, 0, 0};
  return key;
}

}  // namespace

Key number(const char* name, float Config::*field, float minimum, float maximum, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Number, effect);
  key.info.minimum = minimum, key.info.maximum = maximum;
  key.allowedText = formatFloat(minimum) + " .. " + formatFloat(maximum);
  key.parse = [=](Config& c, const std::string& v) { return parseFloat(name, v, minimum, maximum, c.*field); };
  key.print = [=](const Config& c) { return formatFloat(c.*field); };
  key.check = [=](const Config& c) -> Status {
    const float v = c.*field;
    if (std::isfinite(v) && v >= minimum && v <= maximum) return Status::ok();
    std::ostringstream message;
    message << std::setprecision(9) << "config key '" << name << "': value " << v << " is not a number in [" << minimum
            << ", " << maximum << "]";
    return invalid(message.str());
  };
  return key;
}

Key integer(const char* name, int Config::*field, int minimum, int maximum, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Integer, effect);
  key.info.minimum = float(minimum), key.info.maximum = float(maximum);
  key.allowedText = std::to_string(minimum) + " .. " + std::to_string(maximum);
  key.parse = [=](Config& c, const std::string& v) { return parseInt(name, v, minimum, maximum, c.*field); };
  key.print = [=](const Config& c) { return std::to_string(c.*field); };
  key.check = [=](const Config& c) -> Status {
    if (c.*field >= minimum && c.*field <= maximum) return Status::ok();
    return invalid("config key '" + std::string(name) + "': value " + std::to_string(c.*field) +
                   " is not an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) + "]");
  };
  return key;
}

// An integer from a short list (sample counts, factors).
Key choice(const char* name, int Config::*field, const std::vector<int>& allowed, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Choice, effect);
  for (int value : allowed) key.values.push_back(std::to_string(value));
  key.allowedText = listed(allowed);
  const auto refuse = [=](const std::string& value) {
    return invalid("config key '" + std::string(name) + "': unsupported value " + quoted(value) +
                   " (allowed: " + listed(allowed) + ")");
  };
  key.parse = [=](Config& c, const std::string& v) -> Status {
    for (int value : allowed)
      if (v == std::to_string(value)) return c.*field = value, Status::ok();
    return refuse(v);
  };
  key.print = [=](const Config& c) { return std::to_string(c.*field); };
  key.check = [=](const Config& c) -> Status {
    for (int value : allowed)
      if (c.*field == value) return Status::ok();
    return refuse(std::to_string(c.*field));
  };
  return key;
}

Key onOff(const char* name, bool Config::*field, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Switch, effect);
  key.values = {"on", "off"};
  key.allowedText = "on, off";
  key.parse = [=](Config& c, const std::string& v) { return parseBool(name, v, c.*field); };
  key.print = [=](const Config& c) { return std::string(c.*field ? "on" : "off"); };
  key.check = [](const Config&) { return Status::ok(); };
  return key;
}

Key enumKey(const char* name, std::vector<std::pair<int, std::string>> values, std::function<int(const Config&)> get,
            std::function<void(Config&, int)> set, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Choice, effect);
  for (const auto& value : values) key.values.push_back(value.second);
  key.allowedText = listed(key.values);
  const std::string allowed = key.allowedText;
  key.parse = [=](Config& c, const std::string& v) -> Status {
    for (const auto& [value, valueName] : values)
      if (v == valueName) return set(c, value), Status::ok();
    return invalid("config key '" + std::string(name) + "': unknown value " + quoted(v) + " (allowed: " + allowed +
                   ")");
  };
  key.print = [=](const Config& c) -> std::string {
    for (const auto& [value, valueName] : values)
      if (get(c) == value) return valueName;
    return "?";
  };
  key.check = [=](const Config& c) -> Status {
    for (const auto& value : values)
      if (get(c) == value.first) return Status::ok();
    return invalid("config key '" + std::string(name) + "': unknown value " + std::to_string(get(c)) +
                   " (allowed: " + allowed + ")");
  };
  return key;
}

Key folder(const char* name, std::string Config::*field, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Text, effect);
  key.allowedText = "a folder";
  key.parse = [=](Config& c, const std::string& v) { return c.*field = v, Status::ok(); };
  key.print = [=](const Config& c) { return c.*field; };
  key.check = [](const Config&) { return Status::ok(); };
  return key;
}

namespace {

Key methodKey() {
  Key key =
      makeKey("method", ConfigKey::Kind::Choice, "which AA method runs; changing it reallocates only what it needs");
  for (const MethodInfo& row : methodTable()) key.values.push_back(row.name);
  key.allowedText = listed(key.values);
  key.parse = [](Config& c, const std::string& v) { return parseMethod(v, c.method); };
  key.print = [](const Config& c) { return std::string(toString(c.method)); };
  key.check = [](const Config& c) {
    return findMethod(c.method) ? Status::ok()
                                : invalid("config key 'method': unknown value " + std::to_string(int(c.method)));
  };
  return key;
}

// A bundle of other keys (presets/*.cfg, embedded), applied in place; it reads back as "none".
Key presetKey() {
  Key key = makeKey("preset", ConfigKey::Kind::Choice,
                    "a bundle of the keys above, tuned by `make presets` (docs/tune.md#presets); keys after it "
                    "override");
  key.values = {"none", "low", "medium", "high", "ultra"};
  key.allowedText = listed(key.values);
  key.parse = [allowed = key.allowedText](Config& c, const std::string& v) -> Status {
    if (v == "none") return Status::ok();
    const auto& files = presets::embeddedFiles();
    const auto found = files.find(v + ".cfg");
    if (found == files.end())
      return invalid("config key 'preset': unknown value " + quoted(v) + " (allowed: " + allowed + ")");
    // Quality keys only: where shaders come from and whether to time them stay the user's.
    std::string lines;
    std::istringstream in(found->second);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("shader_override_dir", 0) != 0 && line.rfind("measure_gpu_time", 0) != 0 &&
          line.rfind("preset", 0) != 0)
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
      choice("supersample", &Config::supersample, {0, 2, 3, 4},
             "G-buffer methods' source: 0 multisampled (samples); m an m x m supersampled G-buffer (the host's model "
             "pass renders at m x its viewport, Plugin::geometryScale), its m^2 sub-positions lit like samples; "
             "reallocates"));
  keys.push_back(
      number("sample_shading", &Config::sampleShading, 0, 1,
             "fraction of samples the host's model pass shades where it draws multisampled (glMinSampleShading): 1 "
             "runs its discard per sample, anti-aliasing cut-out edges, at up to samples x the model pass's cost"));
  for (const TechniqueRow& row : techniqueRegistry())
    if (row.keys)
      for (Key& key : row.keys()) {
        key.info.method = row.info.name;
        keys.push_back(std::move(key));
      }
  keys.push_back(
      onOff("restore_gbuffer_after_shade", &Config::restoreGBufferAfterShade,
            "after a slice method's lighting, resolve into your G-buffer again so later passes read the resolved "
            "surface, not the last slice; off saves one resolve pass"));
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
  if (name == "method") {  // the registry as it is now: a test may register a method after the keys are built
    std::vector<std::string> values;
    for (const MethodInfo& row : methodTable()) values.push_back(row.name);
    return values;
  }
  const Key* key = findKey(name);
  return key ? key->values : std::vector<std::string>{};
}

Status applySetting(Config& config, const std::string& key, const std::string& value) {
  if (const Key* found = findKey(key)) return found->parse(config, trim(value));
  std::string known;
  for (const Key& k : keys()) known += std::string(known.empty() ? "" : ", ") + k.info.name;
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
  for (const Key& key : keys())
    if (Status status = key.check(config); !status) return status;
  return Status::ok();
}

std::string toConfigText(const Config& config) {
  std::string out;
  for (const Key& key : keys()) out += std::string(key.info.name) + "=" + key.print(config) + "\n";
  return out;
}

Status applyMethodSpec(Config& config, const std::string& spec) {
  auto bad = [&spec](const std::string& why) {
    return Error{ErrorCode::InvalidConfig, "method '" + spec + "': " + why};
  };
  std::string rest = spec;
  // Settings after '@' apply to this spec only: resolve@samples=8@resolve_weighting=fso
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
