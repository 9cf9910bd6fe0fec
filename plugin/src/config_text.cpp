// Config as text: `key=value` lines and lists, FreeSpace Open's flags, method specs, and the names of the
// enums' values. Every key goes through applySetting (config_table.cpp).
#include "retroaa/config.h"

#include "config_keys.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace retroaa {

namespace {

template <typename Enum, size_t N>
const char* nameIn(const Named<Enum> (&table)[N], Enum value) {
  for (const Named<Enum>& row : table)
    if (row.value == value) return row.name;
  return "?";
}

}  // namespace

const char* toString(Method method) {
  const MethodInfo* row = findMethod(method);
  return row ? row->name : "?";
}

const char* toString(ResolveWeighting weighting) { return nameIn(kWeightings, weighting); }
const char* toString(ResolveEvenSplit split) { return nameIn(kEvenSplits, split); }
const char* toString(FxaaQuality quality) { return nameIn(kFxaaQualities, quality); }
const char* toString(SmaaQuality quality) { return nameIn(kSmaaQualities, quality); }
const char* toString(SmaaEdgeDetection detection) { return nameIn(kSmaaEdgeDetections, detection); }
const char* toString(EdgeDetector detector) { return nameIn(kEdgeDetectors, detector); }

Status applyConfigText(Config& config, const std::string& text, const std::string& sourceName) {
  Config updated = config;  // a bad line leaves the caller's config untouched
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string content = trimmed(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const size_t equals = content.find('=');
    if (equals == std::string::npos)
      return invalidConfig(sourceName + ":" + std::to_string(number) + ": expected 'key=value', got " +
                           quotedInput(content));
    const Status status = applySetting(updated, trimmed(content.substr(0, equals)), content.substr(equals + 1));
    if (!status) return invalidConfig(sourceName + ":" + std::to_string(number) + ": " + status.error().message);
  }
  config = updated;
  return Status::ok();
}

Status applyConfigFile(Config& config, const std::string& path) {
  // A regular file of bounded size: a directory would read as empty, /dev/zero would never end.
  constexpr std::uintmax_t kMaxBytes = 1u << 20;
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status))
    return invalidConfig(path + ": cannot open config file: it does not exist");
  if (std::filesystem::is_directory(status))
    return invalidConfig(path + ": cannot open config file: it is a directory");
  if (!std::filesystem::is_regular_file(status))
    return invalidConfig(path + ": cannot open config file: it is not a regular file");
  if (const std::uintmax_t bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxBytes)
    return invalidConfig(path + ": cannot open config file: it is " + std::to_string(bytes) +
                         " bytes, more than the 1 MiB allowed");
  std::ifstream in(path);
  if (!in) return invalidConfig(path + ": cannot open config file");
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
    if (!isInteger)
      return invalidConfig("-msaa: value " + quotedInput(value) + " is not an integer (allowed: 0, 4, 8, 16)");
    if (n != 0 && n != 4 && n != 8 && n != 16) {
      warnings.push_back("-msaa " + (value.size() <= 20 ? value : quotedInput(value)) +
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
      return invalidConfig("-aa_preset: value " + quotedInput(value) + " is not an integer in 0..6");
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
  return invalidConfig("unknown FreeSpace Open flag " + quotedInput(flag) +
                       " (known: -msaa, -aa_preset, -post_process_aa)");
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
