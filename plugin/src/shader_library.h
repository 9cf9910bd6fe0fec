// The plugin's GLSL: embedded at build time from shaders/, each file replaceable from an override
// folder. An override that fails to compile falls back to the built-in file, with a warning that
// names the file and the compiler's line.
#pragma once

#include "gl_resources.h"
#include "retroaa/result.h"

#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace retroaa {

struct PluginContext;

// A linked program and the uniforms the plugin sets on it. Their locations are looked up once, when
// the program is built, and the build fails if the shader does not declare one of them: C++ and
// GLSL cannot drift apart silently. (A declared uniform the compiler optimised away has location -1;
// setting it is then a no-op, as GL defines.)
class ShaderProgram {
 public:
  GLuint get() const { return program_.get(); }
  void use() const { glUseProgram(program_.get()); }
  void set(const char* name, int value) const { glProgramUniform1i(get(), location(name), value); }
  void set(const char* name, float value) const { glProgramUniform1f(get(), location(name), value); }
  void set(const char* name, float x, float y) const { glProgramUniform2f(get(), location(name), x, y); }
  void setVec4(const char* name, const float* xyzw) const { glProgramUniform4fv(get(), location(name), 1, xyzw); }
  void setMatrix4(const char* name, const float* columnMajor) const {
    glProgramUniformMatrix4fv(get(), location(name), 1, GL_FALSE, columnMajor);
  }
  void setMatrix4Array(const char* name, int count, const float* columnMajor) const {
    glProgramUniformMatrix4fv(get(), location(name), count, GL_FALSE, columnMajor);
  }
  void setVec2Array(const char* name, int count, const float* xy) const {
    glProgramUniform2fv(get(), location(name), count, xy);
  }
  // Binds `texture` to the unit the shader gives `sampler` (its `layout(binding = N)`, read back when the
  // program was built): units are numbered once, in GLSL. `sampler` must be in the program's uniform list;
  // one the compiler optimised away binds nothing.
  void bindTexture(const char* sampler, GLuint texture) const;
  // The unit of `sampler` (-1: optimised away), for what is bound per unit besides the texture (a sampler
  // object).
  int unit(const char* sampler) const;
  // The uniforms of common/depth.glsl and depth_buffer.glsl: the host's depth encoding and the planes
  // of the frame being resolved.
  void setDepthEncoding(const PluginContext& context) const;
  // The uniforms of common/depth_buffer.glsl alone: the planes of the frame being resolved.
  void setDepthPlanes(const PluginContext& context) const;

 private:
  friend class ShaderLibrary;
  GLint location(const char* name) const;  // a name not declared at build: -1 and an assertion
  GlProgram program_;
  std::vector<std::pair<std::string, GLint>> uniforms_;
  std::vector<std::pair<std::string, int>> samplerUnits_;  // every active sampler (array elements as name[i])
};

// The uniforms common/depth.glsl and depth_buffer.glsl declare (for the uniform list of a program that includes it).
#define RETROAA_DEPTH_BUFFER_UNIFORMS "uDepthNear", "uDepthFar"
#define RETROAA_DEPTH_ENCODING_UNIFORMS "uDepthKnee", "uBackgroundAbove", "uViewDepthRow", RETROAA_DEPTH_BUFFER_UNIFORMS

class ShaderLibrary {
 public:
  using Warn = std::function<void(const std::string&)>;
  ShaderLibrary(ObjectCounter& counter, std::string overrideDirectory, Warn warn);

  // The shared constants (shared_constants.h) and then `defines` are inserted after the #version line
  // ("#define X 1\n..."). Paths are relative to shaders/. `uniforms`: every uniform the C++ side
  // sets, samplers included; a shader that declares none of that name fails with ShaderError naming it.
  // So does a program whose active samplers share a texture unit, or that gives a sampler bound outside
  // it (the G-buffer's, the slice counts and weights: shared_constants.h) another unit than the C++ side.
  Result<ShaderProgram> program(const std::string& vertexPath, const std::string& fragmentPath,
                                const std::string& defines = "", std::initializer_list<const char*> uniforms = {});
  // The same for a compute shader alone.
  Result<ShaderProgram> computeProgram(const std::string& computePath, const std::string& defines = "",
                                       std::initializer_list<const char*> uniforms = {});

 private:
  struct Stage {
    GLenum type;
    std::string path;
  };
  Result<ShaderProgram> build(const std::vector<Stage>& stages, const std::string& defines,
                              std::initializer_list<const char*> uniforms);
  // Source with includes expanded; `fromOverride` says whether the override folder supplied it.
  Result<std::string> source(const std::string& path, bool allowOverride, bool& fromOverride, int depth = 0) const;
  Result<ShaderProgram> link(const std::vector<Stage>& stages, const std::string& defines,
                             const std::vector<std::string>& uniforms, bool allowOverride, bool& usedOverride);

  ObjectCounter& counter_;
  std::string overrideDirectory_;
  Warn warn_;
};

}  // namespace retroaa
