// The builders of config keys (config_keys.h): how a key of each kind parses, prints and checks its field.
#include "config_keys.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace retroaa {

// User input as a message quotes it: at most 80 characters, control and non-ASCII bytes as \xNN, so a
// 10 MB line or a binary file cannot flood or garble a terminal.
std::string quotedInput(const std::string& text) {
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

std::string trimmed(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

Error invalidConfig(const std::string& message) { return Error{ErrorCode::InvalidConfig, message}; }

namespace {

Status parseFloat(const std::string& key, const std::string& value, float minimum, float maximum, float& out) {
  char* end = nullptr;
  const double parsed = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(parsed) || parsed < minimum ||
      parsed > maximum) {
    std::ostringstream message;
    message << "config key '" << key << "': value " << quotedInput(value) << " is not a number in [" << minimum << ", "
            << maximum << "]";
    return invalidConfig(message.str());
  }
  out = static_cast<float>(parsed);
  return Status::ok();
}

Status parseInt(const std::string& key, const std::string& value, int minimum, int maximum, int& out) {
  float parsed = 0;
  const Status number = parseFloat(key, value, float(minimum), float(maximum), parsed);
  if (!number || parsed != std::floor(parsed))
    return invalidConfig("config key '" + key + "': value " + quotedInput(value) + " is not an integer in [" +
                         std::to_string(minimum) + ", " + std::to_string(maximum) + "]");
  out = int(parsed);
  return Status::ok();
}

Status parseBool(const std::string& key, const std::string& value, bool& out) {
  if (value == "on" || value == "true" || value == "1") return out = true, Status::ok();
  if (value == "off" || value == "false" || value == "0") return out = false, Status::ok();
  return invalidConfig("config key '" + key + "': value " + quotedInput(value) + " is not a switch (allowed: on, off)");
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
  key.info = ConfigKey{name, "", "", effect, kind, 0, 0, {}};
  return key;
}

}  // namespace

Key choiceOfNames(const char* name, std::vector<std::string> values, const char* effect) {
  Key key = makeKey(name, ConfigKey::Kind::Choice, effect);
  key.allowedText = listed(values);
  key.values = std::move(values);
  return key;
}

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
    return invalidConfig(message.str());
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
    return invalidConfig("config key '" + std::string(name) + "': value " + std::to_string(c.*field) +
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
    return invalidConfig("config key '" + std::string(name) + "': unsupported value " + quotedInput(value) +
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
    return invalidConfig("config key '" + std::string(name) + "': unknown value " + quotedInput(v) +
                         " (allowed: " + allowed + ")");
  };
  key.print = [=](const Config& c) -> std::string {
    for (const auto& [value, valueName] : values)
      if (get(c) == value) return valueName;
    return "?";
  };
  key.check = [=](const Config& c) -> Status {
    for (const auto& value : values)
      if (get(c) == value.first) return Status::ok();
    return invalidConfig("config key '" + std::string(name) + "': unknown value " + std::to_string(get(c)) +
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

}  // namespace retroaa
