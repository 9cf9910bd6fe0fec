#include "second_renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace host {

namespace {
bool emits(const Material& material) { return glm::dot(material.emissive, glm::vec3(1.0f)) > 0.0f; }
}  // namespace

SecondRenderer::SecondRenderer(const Scene& scene, int width, int height, bool worldPositionTarget)
    : scene_(scene),
      worldPositionTarget_(worldPositionTarget),
      geometryProgram_("shaders/second/geometry.vert", "shaders/second/geometry.frag"),
      sunProgram_("shaders/fullscreen.vert", "shaders/second/sun.frag"),
      pointProgram_("shaders/second/point.vert", "shaders/second/point.frag"),
      forwardProgram_("shaders/second/geometry.vert", "shaders/second/forward.frag"),
      presentProgram_("shaders/fullscreen.vert", "shaders/second/present.frag") {
  for (const Object& object : scene_.objects) meshes_.push_back(uploadMesh(object.mesh));
  materialTextures_ = std::make_unique<MaterialTextures>(scene_.materials);
  sphere_ = uploadMesh(generate::sphere(1.0f, 3));
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  emptyVertexArray_ = VertexArray(vao);
  createTargets(width, height);
}

SecondRenderer::~SecondRenderer() = default;

namespace {
// Its G-buffer: octahedral normals, albedo and specular, depth, and world positions where asked for.
constexpr GLenum kNormalFormat = GL_RG16F, kAlbedoSpecularFormat = GL_RGBA8, kDepthFormat = GL_DEPTH_COMPONENT32F,
                 kWorldPositionFormat = GL_RGBA32F;
}  // namespace

uint64_t SecondRenderer::gbufferBytesPerSample(bool worldPositionTarget) {
  return texelBytes(kNormalFormat) + texelBytes(kAlbedoSpecularFormat) + texelBytes(kDepthFormat) +
         (worldPositionTarget ? texelBytes(kWorldPositionFormat) : 0);
}

void SecondRenderer::createTargets(int width, int height) {
  normal_ = makeTexture2D(kNormalFormat, width, height, "second.gbuffer.normal");
  albedoSpecular_ = makeTexture2D(kAlbedoSpecularFormat, width, height, "second.gbuffer.albedo_specular");
  depth_ = makeTexture2D(kDepthFormat, width, height, "second.depth");
  display_ = makeTexture2D(GL_SRGB8_ALPHA8, width, height, "second.display");
  GLuint fbos[2];
  glCreateFramebuffers(2, fbos);
  gbufferFramebuffer_ = Framebuffer(fbos[0]);
  displayFramebuffer_ = Framebuffer(fbos[1]);
  glNamedFramebufferTexture(fbos[0], GL_COLOR_ATTACHMENT0, normal_, 0);
  glNamedFramebufferTexture(fbos[0], GL_COLOR_ATTACHMENT1, albedoSpecular_, 0);
  if (worldPositionTarget_) {
    worldPosition_ = makeTexture2D(kWorldPositionFormat, width, height, "second.gbuffer.world_position");
    glNamedFramebufferTexture(fbos[0], GL_COLOR_ATTACHMENT2, worldPosition_, 0);
  }
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(fbos[0], worldPositionTarget_ ? 3 : 2, drawBuffers);
  glNamedFramebufferTexture(fbos[0], GL_DEPTH_ATTACHMENT, depth_, 0);
  glNamedFramebufferTexture(fbos[1], GL_COLOR_ATTACHMENT0, display_, 0);
  glNamedFramebufferTexture(fbos[1], GL_DEPTH_ATTACHMENT, depth_, 0);
  checkFramebuffer(fbos[0], "second.gbuffer");
  checkFramebuffer(fbos[1], "second.display");
  targets_ = {width,    height,        gbufferFramebuffer_, normal_, albedoSpecular_, depth_, displayFramebuffer_,
              display_, worldPosition_};
  seams_->targetsCreated(targets_);
}

void SecondRenderer::resize(int width, int height) {
  if (width != targets_.width || height != targets_.height) createTargets(width, height);
}

void SecondRenderer::setSeams(SecondSeams* seams) {
  seams_ = seams ? seams : &stockSeams_;
  seams_->targetsCreated(targets_);
}

void SecondRenderer::setStockPath(bool stock) {
  if (stock == (suspendedSeams_ != nullptr)) return;
  SecondSeams* installed = stock ? seams_ : suspendedSeams_;
  suspendedSeams_ = stock ? seams_ : nullptr;
  setSeams(stock ? nullptr : installed);
}

glm::mat4 SecondRenderer::projection(const Camera& camera, glm::vec2 jitterPixels) const {
  // Reversed-Z: near and far swapped in a zero-to-one projection put the near plane at 1, the far at 0.
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(camera.fovYDegrees), float(targets_.width) / float(targets_.height),
                                      camera.farPlane, camera.nearPlane);
  p[2][0] += 2.0f * jitterPixels.x / float(targets_.width);
  p[2][1] += 2.0f * jitterPixels.y / float(targets_.height);
  return p;
}

void SecondRenderer::drawObjects(const Program& program, const glm::mat4& viewProjection, ObjectPass pass,
                                 float time) const {
  glUseProgram(program.get());
  setUniform(program.uniform("uViewProjection"), viewProjection);
  setUniform(program.uniform("uExposure"), scene_.exposure);
  for (size_t i = 0; i < scene_.objects.size(); ++i) {
    const Object& object = scene_.objects[i];
    const Material& material = scene_.materials[object.material];
    const bool glows = emits(material) && material.maps.emissive;
    const bool drawn = pass == ObjectPass::Geometry   ? !emits(material) || glows
                       : pass == ObjectPass::Emissive ? emits(material) && !glows
                                                      : glows;
    if (!drawn) continue;
    const glm::mat4 model = object.transformAt(time);
    setUniform(program.uniform("uModel"), model);
    setUniform(program.uniform("uNormalToWorld"), glm::transpose(glm::inverse(glm::mat3(model))));
    setUniform(program.uniform("uAlbedo"), material.albedo);
    setUniform(program.uniform("uSpecular"), glm::dot(material.specular, glm::vec3(1.0f / 3.0f)));
    setUniform(program.uniform("uEmissive"), material.emissive);
    setUniform(program.uniform("uUvScale"), material.maps.uvScale);
    setUniform(program.uniform("uNormalMapped"), materialTextures_->normalMapped(size_t(object.material)) ? 1 : 0);
    materialTextures_->bind(size_t(object.material));
    glBindVertexArray(meshes_[i].vertexArray);
    glDrawElements(GL_TRIANGLES, meshes_[i].indexCount, GL_UNSIGNED_INT, nullptr);
  }
  materialTextures_->unbind();
}

void SecondRenderer::renderFrame(const Camera& camera, glm::vec2 hostJitter) {
  const int width = targets_.width, height = targets_.height;
  const glm::vec2 jitterPixels = hostJitter + seams_->projectionJitter();
  applyTextureLodBias(seams_->textureLodBias());
  const glm::mat4 viewProjection = projection(camera, jitterPixels) * camera.view();
  StageTimestamps stages(measureTime);  // geometry, its hooks, lighting, forward and post
  stages.stamp(StageTimestamps::FrameStart);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // Geometry: everything but the emissive objects, which the forward pass draws.
  auto geometryInto = [&](GLuint target, int scale) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width * scale, height * scale);
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(target, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(target, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(target, GL_COLOR, 2, zero);  // a draw buffer the target leaves GL_NONE ignores it
    const float farDepth = 0.0f;
    glClearNamedFramebufferfv(target, GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    drawObjects(geometryProgram_, viewProjection, ObjectPass::Geometry, camera.time);
    glDisable(GL_CULL_FACE);
  };
  geometryInto(seams_->geometryTarget(gbufferFramebuffer_), seams_->geometryScale());
  stages.stamp(StageTimestamps::ModelPassEnd);
  FrameView view;
  view.verticalFovRadians = glm::radians(camera.fovYDegrees);
  view.width = width;
  view.height = height;
  view.nearPlane = camera.nearPlane;
  view.farPlane = camera.farPlane;
  view.view = camera.view();
  view.projection = projection(camera, hostJitter);
  seams_->geometryDone(view);
  seams_->geometryAgain([&](GLuint target) { geometryInto(target, 1); });
  stages.stamp(StageTimestamps::HooksEnd);

  seams_->lighting([&](GLuint target) { lightingPass(target, camera, projection(camera, jitterPixels)); },
                   displayFramebuffer_);
  stages.stamp(StageTimestamps::LightingEnd);

  forwardPass(viewProjection, camera.time);
  seams_->frameDone();
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);  // the GL default, for whoever draws next
  stages.stamp(StageTimestamps::FrameEnd);
  stages.readInto(timings_);  // tonemapMs: the forward pass and the AA post pass
}

// Forward: emissive objects over the lit image, tested against the scene's depth.
void SecondRenderer::forwardPass(const glm::mat4& viewProjection, float time) {
  glBindFramebuffer(GL_FRAMEBUFFER, displayFramebuffer_);
  glViewport(0, 0, targets_.width, targets_.height);
  glEnable(GL_FRAMEBUFFER_SRGB);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);
  drawObjects(forwardProgram_, viewProjection, ObjectPass::Emissive, time);
  // Glow maps over their own lit surfaces: the same depth passes, the light adds.
  glDepthFunc(GL_GEQUAL);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  drawObjects(forwardProgram_, viewProjection, ObjectPass::Glow, time);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_FRAMEBUFFER_SRGB);
}

void SecondRenderer::lightingPass(GLuint target, const Camera& camera, const glm::mat4& projection) {
  const glm::mat4 view = camera.view();
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, targets_.width, targets_.height);
  glEnable(GL_FRAMEBUFFER_SRGB);
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(target, GL_COLOR, 0, zero);
  const GLuint inputs[] = {normal_, albedoSpecular_, depth_};
  glBindTextures(0, 3, inputs);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  for (const Program* program : {&sunProgram_, &pointProgram_}) {
    glUseProgram(program->get());
    setUniform(program->uniform("uInverseViewProjection"), glm::inverse(projection * view));
    setUniform(program->uniform("uViewportSize"), glm::vec2(targets_.width, targets_.height));
    setUniform(program->uniform("uCameraPosition"), camera.position);
    setUniform(program->uniform("uExposure"), scene_.exposure);
  }

  glUseProgram(sunProgram_.get());
  setUniform(sunProgram_.uniform("uAmbient"), scene_.ambient);
  setUniform(sunProgram_.uniform("uSkyColor"), scene_.skyColor);
  int directional = 0;
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::Directional || directional == 4) continue;
    const std::string index = "[" + std::to_string(directional++) + "]";
    setUniform(sunProgram_.uniform(("uToLight" + index).c_str()), glm::normalize(-light.direction));
    setUniform(sunProgram_.uniform(("uRadiance" + index).c_str()), light.color * light.intensity);
  }
  setUniform(sunProgram_.uniform("uDirectionalCount"), directional);
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  // Point lights (a tube as a point at its middle, reaching its ends) as additive volumes.
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glUseProgram(pointProgram_.get());
  setUniform(pointProgram_.uniform("uViewProjection"), projection * view);
  glBindVertexArray(sphere_.vertexArray);
  for (const Light& light : scene_.lights) {
    if (light.type == LightType::Directional) continue;
    const glm::vec3 centre = light.type == LightType::Tube ? (light.position + light.end) * 0.5f : light.position;
    const float radius =
        light.radius + (light.type == LightType::Tube ? glm::length(light.end - light.position) * 0.5f : 0.0f);
    setUniform(pointProgram_.uniform("uCentre"), centre);
    setUniform(pointProgram_.uniform("uRadius"), radius);
    setUniform(pointProgram_.uniform("uBoundRadius"), radius * 1.1f);  // the 16-segment sphere lies inside 1
    setUniform(pointProgram_.uniform("uRadiance"), light.color * light.intensity);
    glDrawElements(GL_TRIANGLES, sphere_.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_FRAMEBUFFER_SRGB);
}

void SecondRenderer::present(GLuint radiance) {
  glBindFramebuffer(GL_FRAMEBUFFER, displayFramebuffer_);
  glViewport(0, 0, targets_.width, targets_.height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_FRAMEBUFFER_SRGB);
  glUseProgram(presentProgram_.get());
  glBindTextureUnit(0, radiance);
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_FRAMEBUFFER_SRGB);
}

std::vector<uint8_t> SecondRenderer::readDisplay() const {
  return readTopDown<uint8_t>(display_, targets_.width, targets_.height, GL_UNSIGNED_BYTE);
}

std::vector<float> SecondRenderer::readLight() const {
  const std::vector<uint8_t> display = readDisplay();  // sRGB-encoded: decoded here to linear radiance
  std::vector<float> light(display.size());
  for (size_t i = 0; i < display.size(); ++i) {
    const float c = display[i] / 255.0f;
    light[i] = i % 4 == 3 ? c : c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  }
  return light;
}

}  // namespace host
