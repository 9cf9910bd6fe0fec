#include "ground_truth.h"

#include "gl_objects.h"

#include <algorithm>
#include <cmath>

namespace host {

namespace {

// Accumulated luma moments read back as a spread (standard deviation), top row first.
std::vector<float> readSpread(GLuint moments, int width, int height) {
  std::vector<float> momentPixels(size_t(width) * height * 4), spread(size_t(width) * height);
  glGetTextureImage(moments, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(momentPixels.size() * 4), momentPixels.data());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* m = &momentPixels[(size_t(height - 1 - y) * width + x) * 4];  // GL rows run bottom-up
      spread[size_t(y) * width + x] = std::sqrt(std::fmax(m[1] - m[0] * m[0], 0.0f));
    }
  return spread;
}

// The accumulated radiance, presented for the display image, and the luma moments as a spread, both
// read back top row first.
GroundTruth readBack(Engine& renderer, GLuint radiance, GLuint moments, int samplesPerAxis) {
  const int width = renderer.width(), height = renderer.height();
  renderer.present(radiance);
  GroundTruth truth;
  truth.width = width;
  truth.height = height;
  truth.samplesPerAxis = samplesPerAxis;
  truth.display = renderer.readDisplay();
  truth.radiance.resize(size_t(width) * height * 4);
  glGetTextureImage(radiance, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(truth.radiance.size() * 4),
                    truth.radiance.data());
  truth.lumaStdDev = readSpread(moments, width, height);
  std::vector<float> flipped(truth.radiance.size());
  for (int y = 0; y < height; ++y)  // GL rows run bottom-up
    std::copy_n(truth.radiance.begin() + size_t(height - 1 - y) * width * 4, width * 4,
                flipped.begin() + size_t(y) * width * 4);
  truth.radiance = std::move(flipped);
  return truth;
}

}  // namespace

GroundTruth renderGroundTruth(Engine& renderer, const Camera& camera, int samplesPerAxis, TextureFootprint footprint,
                              BackgroundEdges backgroundEdges) {
  const int width = renderer.width(), height = renderer.height();
  renderer.setStockPath(true);

  Texture radiance = makeTexture2D(GL_RGBA32F, width, height, "host.ground_truth.radiance");
  Texture moments = makeTexture2D(GL_RGBA32F, width, height, "host.ground_truth.luma_moments");
  GLuint fbo = 0;
  glCreateFramebuffers(1, &fbo);
  Framebuffer accumulation(fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, radiance, 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, moments, 0);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo, 2, drawBuffers);
  checkFramebuffer(fbo, "host.ground_truth");
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
  glClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);

  Program accumulate("shaders/fullscreen.vert", "shaders/accumulate.frag", renderer.groundTruthDefines());
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  VertexArray emptyVertexArray(vao);
  const float weight = 1.0f / float(samplesPerAxis * samplesPerAxis);
  if (footprint == TextureFootprint::Supersample) renderer.setTextureLodBias(-std::log2(float(samplesPerAxis)));
  // The edge mask (the luma spread) comes from the scene without its material maps: it marks geometry
  // and lighting edges, and texture detail stays interior, where blurring it shows as a cost. With no
  // maps in the scene one pass writes both.
  bool anyMaps = false;
  for (const Material& material : renderer.scene().materials) anyMaps = anyMaps || material.maps.any();
  auto accumulatePass = [&](bool radianceOut, bool spreadOut) {
    const GLenum buffers[] = {radianceOut ? GLenum(GL_COLOR_ATTACHMENT0) : GLenum(GL_NONE),
                              spreadOut ? GLenum(GL_COLOR_ATTACHMENT1) : GLenum(GL_NONE)};
    glNamedFramebufferDrawBuffers(fbo, 2, buffers);
    for (int sy = 0; sy < samplesPerAxis; ++sy)
      for (int sx = 0; sx < samplesPerAxis; ++sx) {
        const glm::vec2 jitter((sx + 0.5f) / samplesPerAxis - 0.5f, (sy + 0.5f) / samplesPerAxis - 0.5f);
        renderer.renderFrame(camera, jitter);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, width, height);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glUseProgram(accumulate.get());
        glUniform1f(accumulate.uniform("uWeight"), weight);
        glUniform1f(accumulate.uniform("uExposure"), renderer.exposure());
        glBindTextureUnit(0, renderer.radianceTexture());
        glBindVertexArray(emptyVertexArray);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisable(GL_BLEND);
      }
  };
  // The models' edges alone: the spread again with the background's detail off, accumulated and read
  // back on its own before the frames that keep it.
  std::vector<float> modelSpread;
  if (backgroundEdges == BackgroundEdges::Apart && renderer.hasBackgroundDetail()) {
    renderer.setMaterialMapsOn(false);
    renderer.setBackgroundDetailOn(false);
    accumulatePass(false, true);
    renderer.setBackgroundDetailOn(true);
    renderer.setMaterialMapsOn(true);
    modelSpread = readSpread(moments, width, height);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);
  }
  if (anyMaps) {
    renderer.setMaterialMapsOn(false);
    accumulatePass(false, true);
    renderer.setMaterialMapsOn(true);
    accumulatePass(true, false);
  } else {
    accumulatePass(true, true);
  }

  GroundTruth truth = readBack(renderer, radiance, moments, samplesPerAxis);
  truth.modelLumaStdDev = std::move(modelSpread);
  renderer.setTextureLodBias(0.0f);
  renderer.setStockPath(false);
  return truth;
}

}  // namespace host
