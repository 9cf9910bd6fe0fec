// What every pass of one plugin shares: the granted config, the host's layout, the GL objects
// counter, the shader library, the log and the statistics of the frame in flight.
#pragma once

#include "frame_statistics.h"
#include "gl_resources.h"
#include "pass_floor.h"
#include "retroaa/types.h"
#include "shader_library.h"

#include <memory>
#include <string>
#include <vector>

namespace retroaa {

struct ContextCapabilities {
  int maxSamples = 1;               // min of GL_MAX_SAMPLES and the texture sample limits
  bool timerQuery = false;          // GL_TIME_ELAPSED
  bool stencilExport = false;       // ARB_shader_stencil_export
  bool pipelineStatistics = false;  // ARB_pipeline_statistics_query (core in 4.6)
  int maxTextureSize = 0;           // GL_MAX_TEXTURE_SIZE
  uint64_t gbufferBudgetBytes = 0;  // Description::gbufferBudgetBytes (0: none)
};

struct PluginContext {
  Config config;  // as granted
  GBufferLayout layout;
  FrameInfo frame;  // of the last resolve(): its planes decode depth-buffer values in every later pass
  ContextCapabilities capabilities;
  ObjectCounter objects;
  LogCallback log;
  std::vector<std::string> warnings;
  std::unique_ptr<ShaderLibrary> shaders;
  // Full-screen passes draw through it: attribute 0 the rectangle (-1, -1, 3, 3) (common/fullscreen.vert).
  GlVertexArray wholeScreenVertexArray;
  GlBuffer wholeScreenRectangle;
  Stats frameStats;                             // of the frame in flight: what the CPU knows of it (slice count)
  std::unique_ptr<FrameStatistics> statistics;  // what the GPU counts of it, read back frames later
  bool timePasses = false;                      // measure_gpu_time, or a budget that needs the times
  bool lightsIntoFloats = false;                // the layout's lightTexture holds floats (not display values)
  std::unique_ptr<PassFloors> floors;           // measure_pass_floors: each measured pass's floor (null: off)
  double budgetScale = 1.0;                     // multiplies the refinement of Technique::followsBudget (budget mode)

  void warn(const std::string& message);
  // What the plugin chose from the layout, where the layout is as documented: the log at Info, not a warning.
  void inform(const std::string& message);
  uint64_t pixelCount() const { return uint64_t(layout.width) * uint64_t(layout.height); }
  // tan(hfov / width): one pixel's footprint per metre of depth, Eq. 1's scale.
  float footprintTan(const FrameInfo& frame) const;
  void drawFullscreen() const;  // one triangle over the viewport
  // The tiles `tiles` names (two triangles each), or the whole screen where it names none.
  void drawTiles(const TileDraw& tiles) const;
  // Binds `framebuffer` (0: leave the binding) with the layout's viewport and plain state: no blend,
  // depth or stencil test, culling or scissor; all colour channels written.
  void beginFullscreenPass(GLuint framebuffer) const;
  // The same, for a pass that writes gl_FragDepth at every pixel it draws (the depth test enabled with
  // GL_ALWAYS: GL writes depth only with the test on).
  void beginDepthWritingPass(GLuint framebuffer) const;
  // Runs the current compute program over the layout's pixels in tileSize × tileSize work groups, with
  // `outputs` (level 0 of each, in a format that takesImageStores) bound write-only as image units 0, 1, …
  using ImageOutput = retroaa::ImageOutput;
  void dispatchOverScreen(const std::vector<ImageOutput>& outputs, int tileSize) const;
  // The same over a width x height grid of invocations (a pass over tiles, not pixels).
  void dispatchOver(const std::vector<ImageOutput>& outputs, int width, int height, int tileSize) const;
};

// Measures one pass into the frame's statistics when the config asks for it (GPU time, fragment
// invocations); labels it for debuggers.
class ScopedPass {
 public:
  // `minimumBytes`: PassStats::minimumBytes, where the pass's traffic is fixed.
  ScopedPass(PluginContext& context, const char* name, uint64_t minimumBytes = 0);
  ~ScopedPass();
  // The samples per pixel the pass reads of each multisampled input, for its floor (default: every one).
  void floorReadsSamples(int samples) {
    if (context_.floors) context_.floors->setSamplesRead(samples);
  }
  ScopedPass(const ScopedPass&) = delete;
  ScopedPass& operator=(const ScopedPass&) = delete;

 private:
  PluginContext& context_;
};

Status checkFramebuffer(GLuint framebuffer, const char* label);
// The HDR scene colour between shade() and the host's tonemap, which a pass before tonemapping filters: the
// composed target where the layout names one (the callback composes), else the light target.
inline GLuint sceneColourTexture(const GBufferLayout& layout) {
  return layout.composedTexture ? layout.composedTexture : layout.lightTexture;
}
inline GLuint sceneColourFramebuffer(const GBufferLayout& layout) {
  return layout.composedTexture ? layout.composedFramebuffer : layout.lightFramebuffer;
}
// A texture in the scene colour's format and size, and a copy of the scene colour into it.
GlTexture makeLightTargetCopy(PluginContext& context, const char* label, uint64_t& bytes);
void copyLightTarget(const GBufferLayout& layout, GLuint copy);
// Level 0 of one 2D texture into another of the same format, the layout's size.
void copyLayoutTexture(const GBufferLayout& layout, GLuint from, GLuint to);

// A texture with immutable storage: GL_TEXTURE_2D for `samples` = 0, GL_TEXTURE_2D_MULTISAMPLE with
// that many samples otherwise (1 included, so N = 1 runs the same multisample path). Adds its size to `bytes`.
GlTexture makeTexture(PluginContext& context, GLenum internalFormat, int width, int height, int samples,
                      const char* label, uint64_t& bytes);
GlFramebuffer makeFramebuffer(PluginContext& context, const char* label);
// A buffer of `bytes` (GL_DYNAMIC_STORAGE_BIT), `data` in it where given; adds its size to `total`.
GlBuffer makeBuffer(PluginContext& context, GLsizeiptr bytes, const void* data, const char* label, uint64_t& total);
// A vertex array whose attribute 0 gives each instance one rectangle (four floats) of `rectangles`:
// common/fullscreen.vert's input.
GlVertexArray makeRectangleArray(PluginContext& context, GLuint rectangles, const char* label);

// The sized depth format of the host's depth texture: its internal format when sized, else the one its
// depth and stencil sizes and depth type say (an unsized GL_DEPTH_COMPONENT or GL_DEPTH_STENCIL). 0 when
// `texture` is no depth texture. The plugin's MSAA depth uses the same format (a reversed-Z D32F
// host keeps its precision).
GLenum sizedDepthFormat(GLuint texture);
bool hasStencil(GLenum depthFormat);
const char* roleName(AttachmentRole role);  // "Albedo", "NormalGloss", … as messages name it
// The sized colour format of the host's texture: `declared` when it is sized, else the one the texture's
// channel sizes and types say (a host that created it as GL_RGBA, GL_RGB, GL_RG or GL_RED). 0 where
// neither says one (no texture, or sizes no sized format has).
GLenum sizedColourFormat(GLuint texture, GLenum declared);
// The sized format of a host's depth(-stencil) renderbuffer, from its depth and stencil sizes when it
// was created unsized (GL_DEPTH_COMPONENT, GL_DEPTH_STENCIL).
GLenum sizedDepthRenderbufferFormat(GLuint renderbuffer);

// The driver's sample positions of `framebuffer` into `positionsXY` (x, y pairs in [0, 1)); entries
// past the framebuffer's own GL_SAMPLES keep their value. Binds the framebuffer.
void readSamplePositions(GLuint framebuffer, std::vector<float>& positionsXY);

}  // namespace retroaa
