#include "pass_floor.h"

#include "frame_statistics.h"
#include "gl_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace retroaa {

namespace {

enum class Channels { Float, Int, Uint };

Channels channelsOf(GLenum format) {
  switch (format) {
    case GL_R8UI:
    case GL_R16UI:
    case GL_R32UI:
    case GL_RG8UI:
    case GL_RG16UI:
    case GL_RG32UI:
    case GL_RGBA8UI:
    case GL_RGBA16UI:
    case GL_RGBA32UI:
    case GL_RGB10_A2UI: return Channels::Uint;
    case GL_R8I:
    case GL_R16I:
    case GL_R32I:
    case GL_RG8I:
    case GL_RG16I:
    case GL_RG32I:
    case GL_RGBA8I:
    case GL_RGBA16I:
    case GL_RGBA32I: return Channels::Int;
    default: return Channels::Float;
  }
}

// The GLSL sampler type of a sampler uniform the floor reproduces ("": one it does not).
std::string samplerName(GLenum type) {
  switch (type) {
    case GL_SAMPLER_2D: return "sampler2D";
    case GL_INT_SAMPLER_2D: return "isampler2D";
    case GL_UNSIGNED_INT_SAMPLER_2D: return "usampler2D";
    case GL_SAMPLER_2D_MULTISAMPLE: return "sampler2DMS";
    case GL_INT_SAMPLER_2D_MULTISAMPLE: return "isampler2DMS";
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE: return "usampler2DMS";
    default: return "";
  }
}

bool multisampledSampler(GLenum type) {
  return type == GL_SAMPLER_2D_MULTISAMPLE || type == GL_INT_SAMPLER_2D_MULTISAMPLE ||
         type == GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE;
}

// The image format qualifier of a format a compute pass stores into ("": none the floor knows).
std::string imageFormatName(GLenum format) {
  switch (format) {
    case GL_RGBA32F: return "rgba32f";
    case GL_RGBA16F: return "rgba16f";
    case GL_RG32F: return "rg32f";
    case GL_RG16F: return "rg16f";
    case GL_R11F_G11F_B10F: return "r11f_g11f_b10f";
    case GL_R32F: return "r32f";
    case GL_R16F: return "r16f";
    case GL_RGBA16: return "rgba16";
    case GL_RGB10_A2: return "rgb10_a2";
    case GL_RGBA8: return "rgba8";
    case GL_RG16: return "rg16";
    case GL_RG8: return "rg8";
    case GL_R16: return "r16";
    case GL_R8: return "r8";
    case GL_R8UI: return "r8ui";
    case GL_R32UI: return "r32ui";
    case GL_RGBA8UI: return "rgba8ui";
    case GL_RG32UI: return "rg32ui";
    default: return "";
  }
}

// A GL enum or format as a message names it.
std::string hex(GLenum value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04X", unsigned(value));
  return text;
}

struct AttachedTexture {
  GLuint texture = 0;
  GLenum format = 0;
  int samples = 0;
  bool renderbuffer = false;
};

AttachedTexture attachedTo(GLuint framebuffer, GLenum attachment) {
  AttachedTexture attached;
  GLint type = GL_NONE, name = 0;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type == GL_NONE) return attached;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  if (type == GL_RENDERBUFFER) {
    attached.renderbuffer = true;
    return attached;
  }
  attached.texture = GLuint(name);
  GLint format = 0, samples = 0;
  glGetTextureLevelParameteriv(attached.texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  glGetTextureLevelParameteriv(attached.texture, 0, GL_TEXTURE_SAMPLES, &samples);
  attached.format = GLenum(format);
  attached.samples = samples;
  return attached;
}

}  // namespace

void PassFloors::open(const char* passName) {
  if (depth_++ > 0) return;
  pass_ = passName;
  samplesRead_ = 0;
  shapes_.clear();
}

void PassFloors::readInputs(Shape& shape, int width, int height) const {
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  GLint count = 0;
  glGetProgramInterfaceiv(GLuint(program), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint index = 0; index < count; ++index) {
    const GLenum properties[] = {GL_TYPE, GL_ARRAY_SIZE, GL_LOCATION};
    GLint values[3] = {};
    glGetProgramResourceiv(GLuint(program), GL_UNIFORM, GLuint(index), 3, properties, 3, nullptr, values);
    const GLenum type = GLenum(values[0]);
    const bool sampler = (type >= GL_SAMPLER_1D && type <= GL_SAMPLER_2D_SHADOW) ||
                         (type >= GL_SAMPLER_1D_ARRAY && type <= GL_UNSIGNED_INT_SAMPLER_BUFFER) ||
                         (type >= GL_SAMPLER_2D_MULTISAMPLE && type <= GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY) ||
                         type == GL_SAMPLER_2D_RECT || type == GL_SAMPLER_2D_RECT_SHADOW;
    if (!sampler || values[2] < 0) continue;
    if (samplerName(type).empty()) {
      shape.unmeasured = "its program reads a sampler of type " + hex(type) + ", which the floor does not reproduce";
      return;
    }
    for (GLint element = 0; element < values[1]; ++element) {
      GLint unit = 0, texture = 0;
      glGetUniformiv(GLuint(program), values[2] + element, &unit);
      GLint previousUnit = 0;
      glGetIntegerv(GL_ACTIVE_TEXTURE, &previousUnit);
      glActiveTexture(GLenum(GL_TEXTURE0 + unit));
      glGetIntegerv(multisampledSampler(type) ? GL_TEXTURE_BINDING_2D_MULTISAMPLE : GL_TEXTURE_BINDING_2D, &texture);
      glActiveTexture(GLenum(previousUnit));
      if (texture == 0) continue;  // nothing bound: the pass reads nothing there
      Input input;
      input.texture = GLuint(texture);
      input.samplerType = type;
      GLint format = 0, samples = 0, textureWidth = 0, textureHeight = 0;
      glGetTextureLevelParameteriv(input.texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
      glGetTextureLevelParameteriv(input.texture, 0, GL_TEXTURE_SAMPLES, &samples);
      glGetTextureLevelParameteriv(input.texture, 0, GL_TEXTURE_WIDTH, &textureWidth);
      glGetTextureLevelParameteriv(input.texture, 0, GL_TEXTURE_HEIGHT, &textureHeight);
      input.format = GLenum(format);
      input.samplesRead =
          multisampledSampler(type) ? (samplesRead_ > 0 ? std::min(samplesRead_, samples) : samples) : 1;
      // A supersampled input holds m × m texels a pixel; a smaller one (or a lookup table) one at most.
      const int across = std::max(1, textureWidth / std::max(width, 1));
      const int down = std::max(1, textureHeight / std::max(height, 1));
      input.texelsPerPixel = across == down ? across * down : 1;
      shape.inputs.push_back(input);
      shape.bytesPerInvocation +=
          uint64_t(input.samplesRead) * uint64_t(input.texelsPerPixel) * bytesPerTexel(input.format);
    }
  }
}

void PassFloors::recordDraw(const TileDraw& tiles) {
  if (depth_ == 0) return;
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const int width = viewport[2], height = viewport[3];
  Shape shape;
  shape.width = width;
  shape.height = height;
  shape.tiles = tiles;
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  if (framebuffer == 0) {
    shape.unmeasured = "it draws into the default framebuffer";
    shapes_.push_back(shape);
    return;
  }
  GLint maxDrawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  for (GLint i = 0; i < maxDrawBuffers; ++i) {
    GLint buffer = GL_NONE;
    glGetIntegerv(GL_DRAW_BUFFER0 + i, &buffer);
    if (buffer == GL_NONE) continue;
    const AttachedTexture attached = attachedTo(GLuint(framebuffer), GLenum(buffer));
    if (attached.renderbuffer) {
      shape.unmeasured = "it draws into a renderbuffer";
      break;
    }
    if (!attached.texture) continue;
    shape.outputs.push_back({int(i), attached.format, attached.samples});
    shape.samples = attached.samples;
  }
  for (const GLenum attachment : {GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT}) {
    const AttachedTexture attached = attachedTo(GLuint(framebuffer), attachment);
    if (attached.renderbuffer) shape.unmeasured = "its depth or stencil is a renderbuffer";
    if (!attached.texture) continue;
    shape.depthStencil = attached.texture;
    shape.depthStencilFormat = attached.format;
    shape.samples = attached.samples;
  }
  shape.depthTest = glIsEnabled(GL_DEPTH_TEST);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &shape.depthMask);
  glGetIntegerv(GL_DEPTH_FUNC, &shape.depthFunc);
  shape.stencilTest = glIsEnabled(GL_STENCIL_TEST);
  glGetIntegerv(GL_STENCIL_FUNC, &shape.stencilFunc);
  glGetIntegerv(GL_STENCIL_REF, &shape.stencilRef);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &shape.stencilValueMask);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &shape.stencilWriteMask);
  glGetIntegerv(GL_STENCIL_FAIL, &shape.stencilFail);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &shape.stencilDepthFail);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &shape.stencilPass);
  shape.blend = glIsEnabled(GL_BLEND);
  glGetIntegerv(GL_BLEND_SRC_RGB, &shape.blendSrcRgb);
  glGetIntegerv(GL_BLEND_DST_RGB, &shape.blendDstRgb);
  glGetIntegerv(GL_BLEND_SRC_ALPHA, &shape.blendSrcAlpha);
  glGetIntegerv(GL_BLEND_DST_ALPHA, &shape.blendDstAlpha);
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &shape.blendEquationRgb);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &shape.blendEquationAlpha);
  shape.framebufferSrgb = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  shape.sampleShading = glIsEnabled(GL_SAMPLE_SHADING);
  glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &shape.minSampleShading);
  readInputs(shape, width, height);
  // What each invocation writes: one value per output sample it covers (every sample of a full-screen
  // triangle, one under sample shading), twice under blending (the destination is read); the depth likewise.
  const uint64_t samplesWritten = shape.sampleShading || shape.samples == 0 ? 1 : uint64_t(shape.samples);
  for (const Output& output : shape.outputs)
    shape.bytesPerInvocation += samplesWritten * bytesPerTexel(output.format) * (shape.blend ? 2 : 1);
  if (shape.depthStencil && shape.depthTest && shape.depthMask)
    shape.bytesPerInvocation += samplesWritten * bytesPerTexel(shape.depthStencilFormat);
  shapes_.push_back(shape);
}

void PassFloors::recordDispatch(const std::vector<ImageOutput>& outputs, int width, int height, int tileSize) {
  if (depth_ == 0) return;
  Shape shape;
  shape.compute = true;
  shape.width = width;
  shape.height = height;
  shape.tileSize = tileSize;
  for (size_t unit = 0; unit < outputs.size(); ++unit) {
    if (imageFormatName(outputs[unit].format).empty()) shape.unmeasured = "it stores a format the floor does not know";
    shape.outputs.push_back({int(unit), outputs[unit].format, 0});
    shape.bytesPerInvocation += bytesPerTexel(outputs[unit].format);
  }
  readInputs(shape, width, height);
  shapes_.push_back(shape);
}

void PassFloors::close(FrameStatistics& statistics, GLuint wholeScreenVertexArray) {
  if (depth_ == 0 || --depth_ > 0) return;
  const std::string floorName = pass_ + ".floor";
  if (shapes_.empty()) {
    statistics.addUnmeasuredPass(floorName, "the pass issues no draw or dispatch of the plugin's own");
    return;
  }
  GlStateGuard hostState;  // whatever the replay binds and enables is put back
  for (const Shape& shape : shapes_) {
    if (!shape.unmeasured.empty()) {
      statistics.addUnmeasuredPass(floorName, shape.unmeasured);
      continue;
    }
    replay(shape, statistics, wholeScreenVertexArray);
  }
  shapes_.clear();
}

const ShaderProgram* PassFloors::program(const Shape& shape) {
  std::string inputs, reads, outputs, writes;
  for (size_t i = 0; i < shape.inputs.size(); ++i) {
    const Input& input = shape.inputs[i];
    const std::string name = "uIn" + std::to_string(i);
    inputs +=
        "layout(binding = " + std::to_string(i) + ") uniform " + samplerName(input.samplerType) + " " + name + "; ";
    const int across = input.texelsPerPixel > 1 ? int(std::lround(std::sqrt(double(input.texelsPerPixel)))) : 1;
    const std::string size =
        multisampledSampler(input.samplerType) ? "textureSize(" + name + ")" : "textureSize(" + name + ", 0)";
    reads += "for (int t = 0; t < " + std::to_string(input.texelsPerPixel) + "; ++t) for (int s = 0; s < " +
             std::to_string(input.samplesRead) + "; ++s) sum += vec4(texelFetch(" + name + ", min(pixel * " +
             std::to_string(across) + " + ivec2(t % " + std::to_string(across) + ", t / " + std::to_string(across) +
             "), " + size + " - 1), " + (multisampledSampler(input.samplerType) ? "s" : "0") + ")); ";
  }
  for (const Output& output : shape.outputs) {
    const std::string name = "uOut" + std::to_string(output.location);
    const Channels channels = channelsOf(output.format);
    const std::string value = channels == Channels::Uint  ? "uvec4(abs(sum))"
                              : channels == Channels::Int ? "ivec4(sum)"
                                                          : "sum";
    if (shape.compute) {
      const std::string prefix = channels == Channels::Uint ? "u" : channels == Channels::Int ? "i" : "";
      outputs += "layout(binding = " + std::to_string(output.location) + ", " + imageFormatName(output.format) +
                 ") writeonly uniform " + prefix + "image2D " + name + "; ";
      writes += "imageStore(" + name + ", pixel, " + value + "); ";
    } else {
      const std::string type = channels == Channels::Uint ? "uvec4" : channels == Channels::Int ? "ivec4" : "vec4";
      outputs += "layout(location = " + std::to_string(output.location) + ") out " + type + " " + name + "; ";
      writes += name + " = " + value + "; ";
    }
  }
  if (!shape.compute && shape.depthStencil && shape.depthTest && shape.depthMask)
    writes += "gl_FragDepth = fract(abs(sum.x)); ";
  // A draw that writes only its stencil (a marking pass) still fetches what the pass fetched: the test
  // keeps the compiler from dropping reads whose sum nothing stores.
  if (!shape.compute && shape.outputs.empty() && writes.empty() && !reads.empty())
    writes += "if (isnan(sum.x)) discard; ";
  std::string defines = "#define FLOOR_INPUTS " + inputs + "\n#define FLOOR_READ " + reads +
                        "\n#define FLOOR_OUTPUTS " + outputs + "\n#define FLOOR_WRITE " + writes + "\n";
  if (shape.compute)
    defines += "#define FLOOR_TILE " + std::to_string(shape.tileSize) + "\n#define FLOOR_SIZE ivec2(" +
               std::to_string(shape.width) + ", " + std::to_string(shape.height) + ")\n";
  auto found = programs_.find(defines);
  if (found != programs_.end()) return &found->second;
  Result<ShaderProgram> built = shape.compute ? shaders_.computeProgram("floor/floor.comp", defines)
                                              : shaders_.program("common/fullscreen.vert", "floor/floor.frag", defines);
  if (!built) {
    programFailure_ = built.error().message;
    return nullptr;
  }
  return &programs_.emplace(defines, std::move(built.value())).first->second;
}

GLuint PassFloors::scratchTexture(GLenum format, int width, int height, int samples, int slot) {
  const std::string key = hex(format) + "/" + std::to_string(width) + "x" + std::to_string(height) + "/" +
                          std::to_string(samples) + "/" + std::to_string(slot);
  auto found = textures_.find(key);
  if (found != textures_.end()) return found->second.get();
  GLuint texture = 0;
  glCreateTextures(samples > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, 1, &texture);
  if (samples > 0)
    glTextureStorage2DMultisample(texture, samples, format, width, height, GL_TRUE);
  else
    glTextureStorage2D(texture, 1, format, width, height);
  glObjectLabel(GL_TEXTURE, texture, -1, "retroaa.floor.scratch");
  return textures_.emplace(key, GlTexture(objects_, texture)).first->second.get();
}

GLuint PassFloors::scratchFramebuffer(const Shape& shape) {
  // The depth-stencil is the pass's own where the pass only tests it (the same pixels pass), a scratch
  // copy where it writes it.
  const bool writesDepthStencil =
      shape.depthStencil && ((shape.depthTest && shape.depthMask) || (shape.stencilTest && shape.stencilWriteMask));
  std::vector<GLuint> colours;
  for (const Output& output : shape.outputs)
    colours.push_back(scratchTexture(output.format, shape.width, shape.height, output.samples, output.location));
  GLuint depthStencil = shape.depthStencil;
  if (writesDepthStencil) {
    depthStencil = scratchTexture(shape.depthStencilFormat, shape.width, shape.height, shape.samples, -1);
    const bool testReadsIt =
        (shape.depthTest && shape.depthFunc != GL_ALWAYS) || (shape.stencilTest && shape.stencilFunc != GL_ALWAYS);
    if (testReadsIt)  // outside the floor's timer: the pass found these values in place
      glCopyImageSubData(shape.depthStencil, shape.samples > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, 0, 0, 0, 0,
                         depthStencil, shape.samples > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, 0, 0, 0, 0,
                         shape.width, shape.height, 1);
  }
  std::string key = std::to_string(depthStencil);
  for (size_t i = 0; i < colours.size(); ++i)
    key += "/" + std::to_string(shape.outputs[i].location) + ":" + std::to_string(colours[i]);
  auto found = framebuffers_.find(key);
  if (found != framebuffers_.end()) return found->second.get();
  GLuint framebuffer = 0;
  glCreateFramebuffers(1, &framebuffer);
  GLint maxDrawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  std::vector<GLenum> drawBuffers(size_t(maxDrawBuffers), GL_NONE);
  for (size_t i = 0; i < colours.size(); ++i) {
    const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + shape.outputs[i].location);
    glNamedFramebufferTexture(framebuffer, attachment, colours[i], 0);
    drawBuffers[size_t(shape.outputs[i].location)] = attachment;
  }
  glNamedFramebufferDrawBuffers(framebuffer, GLsizei(drawBuffers.size()), drawBuffers.data());
  if (depthStencil) {
    GLint depthBits = 0, stencilBits = 0;
    glGetTextureLevelParameteriv(depthStencil, 0, GL_TEXTURE_DEPTH_SIZE, &depthBits);
    glGetTextureLevelParameteriv(depthStencil, 0, GL_TEXTURE_STENCIL_SIZE, &stencilBits);
    const GLenum attachment = !stencilBits ? GL_DEPTH_ATTACHMENT
                              : depthBits  ? GL_DEPTH_STENCIL_ATTACHMENT
                                           : GL_STENCIL_ATTACHMENT;
    glNamedFramebufferTexture(framebuffer, attachment, depthStencil, 0);
  }
  glObjectLabel(GL_FRAMEBUFFER, framebuffer, -1, "retroaa.floor.target");
  return framebuffers_.emplace(key, GlFramebuffer(objects_, framebuffer)).first->second.get();
}

void PassFloors::replay(const Shape& shape, FrameStatistics& statistics, GLuint wholeScreenVertexArray) {
  const std::string floorName = pass_ + ".floor";
  const ShaderProgram* floor = program(shape);
  if (!floor) {
    statistics.addUnmeasuredPass(floorName, "its floor program did not build: " + programFailure_);
    return;
  }
  const GLuint target = shape.compute ? 0 : scratchFramebuffer(shape);
  if (target && glCheckNamedFramebufferStatus(target, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    statistics.addUnmeasuredPass(floorName, "its scratch target is incomplete");
    return;
  }
  floor->use();
  for (size_t unit = 0; unit < shape.inputs.size(); ++unit) glBindTextureUnit(GLuint(unit), shape.inputs[unit].texture);
  std::vector<GLuint> images;
  if (shape.compute) {
    for (const Output& output : shape.outputs) {
      const GLuint image = scratchTexture(output.format, shape.width, shape.height, 0, output.location);
      glBindImageTexture(GLuint(output.location), image, 0, GL_FALSE, 0, GL_WRITE_ONLY, output.format);
    }
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, shape.width, shape.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    shape.depthTest ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
    glDepthMask(shape.depthMask);
    glDepthFunc(GLenum(shape.depthFunc));
    shape.stencilTest ? glEnable(GL_STENCIL_TEST) : glDisable(GL_STENCIL_TEST);
    glStencilFunc(GLenum(shape.stencilFunc), shape.stencilRef, GLuint(shape.stencilValueMask));
    glStencilOp(GLenum(shape.stencilFail), GLenum(shape.stencilDepthFail), GLenum(shape.stencilPass));
    glStencilMask(GLuint(shape.stencilWriteMask));
    shape.blend ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
    glBlendFuncSeparate(GLenum(shape.blendSrcRgb), GLenum(shape.blendDstRgb), GLenum(shape.blendSrcAlpha),
                        GLenum(shape.blendDstAlpha));
    glBlendEquationSeparate(GLenum(shape.blendEquationRgb), GLenum(shape.blendEquationAlpha));
    shape.framebufferSrgb ? glEnable(GL_FRAMEBUFFER_SRGB) : glDisable(GL_FRAMEBUFFER_SRGB);
    shape.sampleShading ? glEnable(GL_SAMPLE_SHADING) : glDisable(GL_SAMPLE_SHADING);
    glMinSampleShading(shape.minSampleShading);
    glBindVertexArray(shape.tiles.vertexArray ? shape.tiles.vertexArray : wholeScreenVertexArray);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, shape.tiles.commands);
  }
  statistics.beginPass(floorName.c_str(), true, 0, shape.bytesPerInvocation);
  if (shape.compute) {
    glDispatchCompute(GLuint((shape.width + shape.tileSize - 1) / shape.tileSize),
                      GLuint((shape.height + shape.tileSize - 1) / shape.tileSize), 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
  } else if (shape.tiles.vertexArray) {
    glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(shape.tiles.offset));
  } else {
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  statistics.endPass();
  if (shape.compute)
    for (const Output& output : shape.outputs)
      glBindImageTexture(GLuint(output.location), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, output.format);
}

void PassFloors::release() {
  shapes_.clear();
  programs_.clear();
  framebuffers_.clear();
  textures_.clear();
  depth_ = 0;
}

}  // namespace retroaa
