#pragma once
// JSON files a user can point the tools at (scenes, camera paths, goldens, caches, capture records), read
// within bounds before any document is built.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <initializer_list>
#include <string>

namespace host {

// A root object's array and the most elements it may hold.
struct RootArrayLimit {
  const char* key;
  size_t most;
};

// `text` parsed, once a linear scan has found it nested no deeper than 32 levels, holding no more than
// 4 M values in all and no more elements in each of `rootArrayLimits`' arrays than allowed; otherwise,
// or on a syntax error, a SceneError naming `fileName`, the field and the limit.
nlohmann::json parseBoundedJson(const std::string& text, const std::string& fileName,
                                std::initializer_list<RootArrayLimit> rootArrayLimits = {});

}  // namespace host
