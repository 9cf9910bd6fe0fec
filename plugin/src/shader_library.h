// The plugin's GLSL: embedded at build time from shaders/, each file replaceable from an override
// folder. An override that fails to compile falls back to the built-in file, with a warning that
// names the file and the compiler's line.
#pragma once

#include "gl_resources.h"
#include "retroaa/result.h"

#include <functional>
#include <string>

namespace retroaa {

class ShaderLibrary {
 public:
  using Warn = std::function<void(const std::string&)>;
  ShaderLibrary(ObjectCounter& counter, std::string overrideDirectory, Warn warn);

  // `defines` is inserted after the #version line ("#define X 1\n..."). Paths are relative to shaders/.
  Result<GlProgram> program(const std::string& vertexPath, const std::string& fragmentPath,
                            const std::string& defines = "");

 private:
  // Source with includes expanded; `fromOverride` says whether the override folder supplied it.
  Result<std::string> source(const std::string& path, bool allowOverride, bool& fromOverride, int depth = 0) const;
  Result<GlProgram> link(const std::string& vertexPath, const std::string& fragmentPath,
                         const std::string& defines, bool allowOverride, bool& usedOverride);

  ObjectCounter& counter_;
  std::string overrideDirectory_;
  Warn warn_;
};

}  // namespace retroaa
