// The host engine's small GL helpers: owning handles and program building from embedded sources.
// (The plugin has its own: it must not depend on its host.)
#pragma once

#include "mesh.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace host {

// The host's shaders/ and scenes/ files, embedded at build time, keyed by path ("shaders/model.frag").
const std::map<std::string, std::string>& embeddedFiles();

// Owns one GL name; `Deleter` is a function like glDeleteTextures(count, names).
template <void (*Deleter)(GLsizei, const GLuint*)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint name) : name_(name) {}
  ~GlName() { reset(); }
  GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  void reset() {
    if (name_) Deleter(1, &name_);
    name_ = 0;
  }
  GLuint get() const { return name_; }
  operator GLuint() const { return name_; }

 private:
  GLuint name_ = 0;
};

inline void deleteTextures(GLsizei n, const GLuint* names) { glDeleteTextures(n, names); }
inline void deleteBuffers(GLsizei n, const GLuint* names) { glDeleteBuffers(n, names); }
inline void deleteFramebuffers(GLsizei n, const GLuint* names) { glDeleteFramebuffers(n, names); }
inline void deleteVertexArrays(GLsizei n, const GLuint* names) { glDeleteVertexArrays(n, names); }
inline void deleteQueries(GLsizei n, const GLuint* names) { glDeleteQueries(n, names); }
inline void deleteSamplers(GLsizei n, const GLuint* names) { glDeleteSamplers(n, names); }
using Texture = GlName<deleteTextures>;
using Buffer = GlName<deleteBuffers>;
using Framebuffer = GlName<deleteFramebuffers>;
using VertexArray = GlName<deleteVertexArrays>;
using Query = GlName<deleteQueries>;
using Sampler = GlName<deleteSamplers>;

class Program {
 public:
  Program() = default;
  // Sources are embedded file names (shaders/...); "#include \"x\"" lines pull in other embedded files.
  // `defines` ("#define X 1\n...") go after each stage's #version line.
  Program(const std::string& vertexFile, const std::string& fragmentFile, const std::string& defines = "");
  ~Program();
  Program(Program&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  GLuint get() const { return name_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(name_, name); }

 private:
  GLuint name_ = 0;
};

// Bytes a texel of `format` takes, for the formats the hosts allocate (0 for any other).
uint64_t texelBytes(GLenum format);
Texture makeTexture2D(GLenum internalFormat, int width, int height, const char* label);

// Uniforms of the bound program, by location.
inline void setUniform(GLint location, const glm::mat4& m) {
  glUniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(m));
}
inline void setUniform(GLint location, const glm::mat3& m) {
  glUniformMatrix3fv(location, 1, GL_FALSE, glm::value_ptr(m));
}
inline void setUniform(GLint location, glm::vec3 v) { glUniform3fv(location, 1, glm::value_ptr(v)); }
inline void setUniform(GLint location, glm::vec2 v) { glUniform2fv(location, 1, glm::value_ptr(v)); }
inline void setUniform(GLint location, float v) { glUniform1f(location, v); }
inline void setUniform(GLint location, int v) { glUniform1i(location, v); }

// A texture's RGBA texels as `type` (GL_UNSIGNED_BYTE for uint8_t, GL_FLOAT for float), rows top-down
// as images run (GL's run bottom-up).
template <typename T>
std::vector<T> readTopDown(GLuint texture, int width, int height, GLenum type) {
  std::vector<T> pixels(size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture, 0, GL_RGBA, type, static_cast<GLsizei>(pixels.size() * sizeof(T)), pixels.data());
  const size_t row = size_t(width) * 4;
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(pixels.begin() + y * row, pixels.begin() + (y + 1) * row, pixels.begin() + (height - 1 - y) * row);
  return pixels;
}

// A mesh in GPU buffers: positions at attribute 0, normals at 1, texture coordinates at 2, tangents
// at 3; indexed triangles.
struct GpuMesh {
  VertexArray vertexArray;
  Buffer vertices, indices;
  GLsizei indexCount = 0;
};
GpuMesh uploadMesh(const Mesh& mesh);
void checkFramebuffer(GLuint framebuffer, const char* label);  // throws with the status name

}  // namespace host
