// The GL boilerplate that both the library (plugin/) and the in-repo engines (engine-patch/) need, and
// neither may take from the other: the engines stand for a foreign engine that knows nothing of the
// plugin, and the library needs only a compiler, CMake and libepoxy. Header-only, so that each links it
// into itself.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace gl_basics {

// Compiles one stage of `source`; 0 and the driver's info log where it does not compile.
inline GLuint compileStage(GLenum stage, const std::string& source, std::string& log) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return shader;
  char buffer[4096] = {};
  glGetShaderInfoLog(shader, sizeof buffer, nullptr, buffer);
  log = buffer;
  glDeleteShader(shader);
  return 0;
}

// A single-level 2D texture with immutable storage, read texel for texel (nearest, clamped).
inline GLuint createTexelTexture2D(GLenum internalFormat, int width, int height) {
  GLuint name = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &name);
  glTextureStorage2D(name, 1, internalFormat, width, height);
  glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return name;
}

}  // namespace gl_basics
