// A config key's one description (config_table.cpp lists them all): its Config field, type, range or
// names, and effect. The keys of one technique are declared in that technique's file and reach the table
// through its registry row (TechniqueRow::keys); config_table.cpp declares the keys every method shares.
// The builders are in config_keys.cpp.
#pragma once

#include "enum_names.h"
#include "retroaa/config.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace retroaa {

struct Key {
  ConfigKey info;  // the public view; its strings point into the fields below once the table is built
  std::string defaultText, allowedText;
  std::vector<std::string> values;  // every allowed value, for keys with a list of them
  std::function<Status(Config&, const std::string&)> parse;
  std::function<std::string(const Config&)> print;
  std::function<Status(const Config&)> check;  // the parser's rules on the typed field: no text round trip
};

Key number(const char* name, float Config::*field, float minimum, float maximum, const char* effect);
Key integer(const char* name, int Config::*field, int minimum, int maximum, const char* effect);
Key choice(const char* name, int Config::*field, const std::vector<int>& allowed, const char* effect);  // a short list
Key onOff(const char* name, bool Config::*field, const char* effect);
Key folder(const char* name, std::string Config::*field, const char* effect);
// A choice among names whose parse, print and check the caller sets (`preset`).
Key choiceOfNames(const char* name, std::vector<std::string> values, const char* effect);
// An enum: `values` are its {value, name} rows, `get` and `set` the field.
Key enumKey(const char* name, std::vector<std::pair<int, std::string>> values, std::function<int(const Config&)> get,
            std::function<void(Config&, int)> set, const char* effect);

// The helpers every reader of config text shares.
Error invalidConfig(const std::string& message);
// User input as a message quotes it: at most 80 characters, control and non-ASCII bytes as \xNN.
std::string quotedInput(const std::string& text);
std::string trimmed(const std::string& text);  // without leading and trailing blanks

template <typename Enum, size_t N>
Key named(const char* name, Enum Config::*field, const Named<Enum> (&table)[N], const char* effect) {
  std::vector<std::pair<int, std::string>> values;
  for (const Named<Enum>& row : table) values.emplace_back(int(row.value), row.name);
  return enumKey(
      name, std::move(values), [field](const Config& c) { return int(c.*field); },
      [field](Config& c, int value) { c.*field = Enum(value); }, effect);
}

}  // namespace retroaa
