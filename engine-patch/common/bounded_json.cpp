#include "bounded_json.h"

#include "scene.h"

#include <algorithm>
#include <cstdlib>

namespace host {

namespace {

// A JSON string's text as its reader sees it (\uXXXX and the one-letter escapes decoded; a code point past
// ASCII stands as '?'): a key written "obj\u0065cts" is "objects" to the parser, so to the limits too.
std::string unescapedJsonString(const std::string& text, size_t begin, size_t end) {
  std::string out;
  for (size_t i = begin; i < end; ++i) {
    if (text[i] != '\\' || i + 1 >= end) {
      out += text[i];
      continue;
    }
    const char e = text[++i];
    if (e == 'u' && i + 4 < end) {
      const unsigned long code = std::strtoul(text.substr(i + 1, 4).c_str(), nullptr, 16);
      out += code < 0x80 ? char(code) : '?';
      i += 4;
    } else {
      out += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e;
    }
  }
  return out;
}

// What a JSON file's text may hold before it is parsed into a document, found in one linear pass over
// the text (written by hand: nlohmann-json checks none of it, and its callback parser, which could,
// rescans each array after every object it closes, so 10^6 objects took minutes): nesting no deeper than
// kMaxJsonNesting, no more than kMaxJsonValues values in all (each costs the document tens of bytes), and
// no more elements in each of `rootArrayLimits`' arrays of the root object (keys compared as the parser
// reads them) than it allows. Either would otherwise cost gigabytes and seconds before its error. Syntax
// is the parser's to judge.
void scanJsonText(const std::string& text, const std::string& fileName,
                  std::initializer_list<RootArrayLimit> rootArrayLimits) {
  constexpr int kMaxJsonNesting = 32;
  constexpr size_t kMaxJsonValues = 4'000'000;
  int depth = 0;
  bool inString = false, escaped = false, afterColon = false;
  std::string lastRootString;  // the last string read directly in the root object (a key, before ':')
  size_t stringStart = 0;
  const RootArrayLimit* limited = nullptr;  // the root array being counted, while in it
  int limitedDepth = -1;                    // the depth inside it
  size_t elements = 0;                      // its elements so far
  bool limitedEmpty = true;
  size_t values = 1;  // the root; then one per element or member that a ',' or an opening bracket begins
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"') {
        inString = false;
        if (depth == 1) lastRootString = unescapedJsonString(text, stringStart, i);
      }
      continue;
    }
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (limited && depth == limitedDepth && c != ']' && c != ',') limitedEmpty = false;
    if (c == '"') {
      inString = true, stringStart = i + 1;
    } else if (c == '[' || c == '{') {
      ++values;
      if (c == '[' && depth == 1 && afterColon)
        for (const RootArrayLimit& limit : rootArrayLimits)
          if (lastRootString == limit.key) limited = &limit, limitedDepth = depth + 1;
      if (++depth > kMaxJsonNesting)
        throw SceneError(fileName, "(document)",
                         "nested more than " + std::to_string(kMaxJsonNesting) + " levels deep");
    } else if (c == ']' || c == '}') {
      if (limited && depth == limitedDepth) {  // the array closed: its count is known
        elements += limitedEmpty ? 0 : 1;
        if (elements > limited->most)
          throw SceneError(
              fileName, std::string("$.") + limited->key,
              "has " + std::to_string(elements) + " elements (at most " + std::to_string(limited->most) + ")");
        limited = nullptr, limitedDepth = -1, elements = 0, limitedEmpty = true;
      }
      depth = std::max(depth - 1, 0);
    } else if (c == ',') {
      ++values;
      if (limited && depth == limitedDepth) ++elements;
    }
    if (values > kMaxJsonValues)
      throw SceneError(fileName, "(document)", "holds more than " + std::to_string(kMaxJsonValues) + " values");
    afterColon = c == ':';
  }
}

}  // namespace

nlohmann::json parseBoundedJson(const std::string& text, const std::string& fileName,
                                std::initializer_list<RootArrayLimit> rootArrayLimits) {
  scanJsonText(text, fileName, rootArrayLimits);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // syntax errors, and numbers beyond double's range
    throw SceneError(fileName, "(document)", std::string("not valid JSON: ") + e.what());
  }
}

}  // namespace host
