// Owning wrappers for the plugin's GL objects. Each one registers with its plugin's ObjectCounter,
// so a test (and Stats::glObjectsHeld) can prove nothing leaks across resizes and method toggles.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <utility>

namespace retroaa {

struct ObjectCounter {
  int live = 0;
};

enum class GlKind { Texture, Framebuffer, VertexArray, Program, Query, Sampler, Buffer };

template <GlKind Kind>
class GlObject {
 public:
  GlObject() = default;
  GlObject(ObjectCounter& counter, GLuint name) : counter_(&counter), name_(name) {
    if (name_) ++counter_->live;
  }
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept
      : counter_(std::exchange(other.counter_, nullptr)), name_(std::exchange(other.name_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      counter_ = std::exchange(other.counter_, nullptr);
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  void reset() {
    if (!name_) return;
    switch (Kind) {
      case GlKind::Texture: glDeleteTextures(1, &name_); break;
      case GlKind::Framebuffer: glDeleteFramebuffers(1, &name_); break;
      case GlKind::VertexArray: glDeleteVertexArrays(1, &name_); break;
      case GlKind::Program: glDeleteProgram(name_); break;
      case GlKind::Query: glDeleteQueries(1, &name_); break;
      case GlKind::Sampler: glDeleteSamplers(1, &name_); break;
      case GlKind::Buffer: glDeleteBuffers(1, &name_); break;
    }
    --counter_->live;
    name_ = 0;
  }
  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }

 private:
  ObjectCounter* counter_ = nullptr;
  GLuint name_ = 0;
};

using GlTexture = GlObject<GlKind::Texture>;
using GlFramebuffer = GlObject<GlKind::Framebuffer>;
using GlVertexArray = GlObject<GlKind::VertexArray>;
using GlProgram = GlObject<GlKind::Program>;
using GlQuery = GlObject<GlKind::Query>;
using GlSampler = GlObject<GlKind::Sampler>;
using GlBuffer = GlObject<GlKind::Buffer>;

// A fence (glFenceSync), deleted with its owner. Polled, never waited on, in the frame path.
class GlFence {
 public:
  GlFence() = default;
  ~GlFence() { reset(); }
  GlFence(const GlFence&) = delete;
  GlFence& operator=(const GlFence&) = delete;
  void insert() {
    reset();
    sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  }
  bool pending() const { return sync_ != nullptr; }
  // Whether the GPU has passed it (false when none is pending); asks without waiting.
  bool signaled() const {
    if (!sync_) return false;
    GLint status = GL_UNSIGNALED;
    glGetSynciv(sync_, GL_SYNC_STATUS, 1, nullptr, &status);
    return status == GL_SIGNALED;
  }
  void reset() {
    if (sync_) glDeleteSync(sync_);
    sync_ = nullptr;
  }

 private:
  GLsync sync_ = nullptr;
};

// Whether `texture` is a texture whose texels are floats (GL_RGBA16F, GL_R11F_G11F_B10F, ...); false for 0,
// a name that is not a texture, and normalised formats (a display's RGBA8 or sRGB).
bool holdsFloats(GLuint texture);
// Bytes per texel of the formats the plugin allocates (for Stats::bytesHeld).
uint64_t bytesPerTexel(GLenum internalFormat);
// Whether a colour target of this format takes image stores (GL 4.5 core, table 8.27: float and
// normalised formats with one, two or four channels, and R11F_G11F_B10F). sRGB and three-channel
// formats do not.
bool takesImageStores(GLenum internalFormat);

}  // namespace retroaa
