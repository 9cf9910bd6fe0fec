// Each measured pass's floor (measure_pass_floors): a pass of the same shape that moves the same bytes
// and does nothing else, timed in the same frame. Every draw and dispatch of a pass is recorded where the
// plugin issues it (PluginContext::drawFullscreen, drawTiles, dispatchOver): the bound targets' formats and
// sample counts, the fixed-function state (stencil mask, depth writes, blending, sample shading) and the
// textures its program reads. After the pass, each is replayed with a generated shader (shaders/floor/)
// that fetches every texel and sample of those textures once per invocation (or the samples the pass
// reads, PassFloors::setSamplesRead) and writes its sum to the same outputs, into scratch targets of the
// same formats over the same stencil: the same invocations, fetches and writes, no arithmetic. A pass far
// above its floor does work it needn't; one near it is bound by the bytes it must move on this device.
#pragma once

#include "gl_resources.h"
#include "shader_library.h"

#include <map>
#include <string>
#include <vector>

namespace retroaa {

class FrameStatistics;

// A sparse pass's tiles (SliceRenderer::tilesWhereCountAtLeast): a vertex array whose attribute 0 gives
// each instance one tile's rectangle (common/fullscreen.vert), and the indirect draw command in `commands`
// at `offset` that draws them. No vertex array: the whole screen.
struct TileDraw {
  GLuint vertexArray = 0;
  GLuint commands = 0;
  GLintptr offset = 0;
};

// A texture a compute pass writes through an image unit.
struct ImageOutput {
  GLuint texture;
  GLenum format;
};

class PassFloors {
 public:
  PassFloors(ObjectCounter& objects, ShaderLibrary& shaders) : objects_(objects), shaders_(shaders) {}

  // A measured pass begins (nested passes belong to the outermost) and ends: close() replays its draws,
  // each timed as "<pass>.floor"; a pass whose draws the floor cannot reproduce, or that drew nothing of
  // its own (the host's lighting, clears and copies), is reported as unmeasured with the reason.
  void open(const char* passName);
  void close(FrameStatistics& statistics, GLuint wholeScreenVertexArray);
  // The samples per pixel the open pass reads of each multisampled input (0: every sample).
  void setSamplesRead(int samples) { samplesRead_ = samples; }

  void recordDraw(const TileDraw& tiles = {});  // over the viewport as set
  void recordDispatch(const std::vector<ImageOutput>& outputs, int width, int height, int tileSize);

  // The scratch targets and programs held (counted in the plugin's objects; freed with the plugin's
  // other objects on reallocation).
  void release();

 private:
  struct Input {
    GLuint texture = 0;
    GLenum samplerType = 0;
    GLenum format = 0;
    int samplesRead = 1;     // per texel
    int texelsPerPixel = 1;  // a supersampled input: m² texels per pixel
  };
  struct Output {
    int location = 0;  // draw buffer index, or image unit
    GLenum format = 0;
    int samples = 0;  // 0: a single-sample texture
  };
  struct Shape {
    bool compute = false;
    std::vector<Input> inputs;
    std::vector<Output> outputs;
    GLuint depthStencil = 0;  // the target's depth(-stencil) texture (0: none)
    GLenum depthStencilFormat = 0;
    int width = 0, height = 0, samples = 0, tileSize = 0;
    // Fixed-function state as the pass drew.
    GLboolean depthTest = 0, depthMask = 0, stencilTest = 0, blend = 0, framebufferSrgb = 0, sampleShading = 0;
    GLint depthFunc = GL_ALWAYS, stencilFunc = GL_ALWAYS, stencilRef = 0, stencilValueMask = 0xFF, stencilWriteMask = 0,
          stencilFail = GL_KEEP, stencilDepthFail = GL_KEEP, stencilPass = GL_KEEP;
    GLint blendSrcRgb = GL_ONE, blendDstRgb = GL_ZERO, blendSrcAlpha = GL_ONE, blendDstAlpha = GL_ZERO,
          blendEquationRgb = GL_FUNC_ADD, blendEquationAlpha = GL_FUNC_ADD;
    GLfloat minSampleShading = 0;
    TileDraw tiles;          // the tiles the pass drew (none: the whole screen)
    std::string unmeasured;  // why the floor cannot reproduce it (empty: it can)
    uint64_t bytesPerInvocation = 0;
  };
  void readInputs(Shape& shape, int width, int height) const;
  void replay(const Shape& shape, FrameStatistics& statistics, GLuint wholeScreenVertexArray);
  const ShaderProgram* program(const Shape& shape);
  GLuint scratchFramebuffer(const Shape& shape);
  GLuint scratchTexture(GLenum format, int width, int height, int samples, int slot);

  ObjectCounter& objects_;
  ShaderLibrary& shaders_;
  int depth_ = 0;
  std::string pass_;
  int samplesRead_ = 0;
  std::vector<Shape> shapes_;
  std::map<std::string, ShaderProgram> programs_;
  std::map<std::string, GlTexture> textures_;
  std::map<std::string, GlFramebuffer> framebuffers_;
  std::string programFailure_;  // a floor program that did not build: every later floor reports it
};

}  // namespace retroaa
