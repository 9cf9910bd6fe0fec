#include "renderer.h"

#include <algorithm>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace host {

namespace {

// opengl_setup_scene_textures(): FSO's G-buffer attachments (colour, position, normal, specular, emissive) and
// depth, with the velocity attachment of scenes whose objects move.
constexpr GLenum kGBufferFormats[] = {GL_RGBA16F, GL_RGBA16F, GL_RGBA16F, GL_RGBA8, GL_RGBA16F};
constexpr GLenum kDepthStencilFormat = GL_DEPTH24_STENCIL8, kVelocityFormat = GL_RG16F;

// The position-depth encoding's #defines, for every program that includes depth_codec.glsl.
std::string positionDepthDefines(const Scene& scene) {
  if (scene.positionDepth != PositionDepth::FsoCompressed) return "";
  char text[96];  // FSO injects GLOBAL_FAR_Z the same way, as a literal
  std::snprintf(text, sizeof text, "#define FSO_COMPRESSED_Z 1\n#define GLOBAL_FAR_Z %.9e\n",
                double(scene.camera.farPlane));
  return text;
}

bool writesVelocity(const Scene& scene) {
  return scene.objectsMove() && scene.objectMotion == Scene::ObjectMotion::Velocity;
}

}  // namespace

std::vector<FrameView::MovingBox> Renderer::movingBoxes() const {
  std::vector<FrameView::MovingBox> boxes;
  for (const Object& object : scene_.objects) {
    if (object.velocity == glm::vec3(0.0f) || object.mesh.vertices.empty()) continue;
    glm::vec3 low(1e30f), high(-1e30f);
    for (const Vertex& vertex : object.mesh.vertices)
      low = glm::min(low, vertex.position), high = glm::max(high, vertex.position);
    // The cube [-1, 1]³ onto the mesh's bounds, a little larger (an engine's boxes are seldom tight).
    const glm::mat4 cubeToMesh =
        glm::scale(glm::translate(glm::mat4(1.0f), 0.5f * (low + high)), 0.5f * (high - low) * 1.05f + 1e-3f);
    boxes.push_back(
        {object.transformAt(motion_.currentTime) * cubeToMesh, object.transformAt(motion_.previousTime) * cubeToMesh});
  }
  return boxes;
}

Renderer::Renderer(const Scene& scene, int width, int height)
    : scene_(scene),
      modelProgram_("shaders/model.vert", "shaders/model.frag",
                    positionDepthDefines(scene) +
                        (scene.depthBuffer == DepthBuffer::Logarithmic ? "#define LOGARITHMIC_DEPTH 1\n" : "")),
      backgroundProgram_("shaders/fullscreen.vert", "shaders/background.frag", positionDepthDefines(scene)),
      ambientProgram_("shaders/fullscreen.vert", "shaders/light_ambient_directional.frag", positionDepthDefines(scene)),
      pointProgram_("shaders/light_volume.vert", "shaders/light_point.frag", positionDepthDefines(scene)),
      emissiveProgram_("shaders/fullscreen.vert", "shaders/emissive.frag", positionDepthDefines(scene)),
      tonemapProgram_("shaders/fullscreen.vert", "shaders/tonemap.frag") {
  for (const Object& object : scene_.objects) meshes_.push_back(uploadMesh(object.mesh));
  materialTextures_ = std::make_unique<MaterialTextures>(scene_.materials);
  // Light volumes must contain their sphere: a 16-segment sphere's faces sit inside radius 1, so
  // the volume is scaled up by 1/cos(pi/16)^2 when drawn.
  sphereVolume_ = uploadMesh(generate::sphere(1.0f, 3));
  boxVolume_ = uploadMesh(generate::box(glm::vec3(2.0f)));
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  emptyVertexArray_ = VertexArray(vao);
  createTargets(width, height);
}

Renderer::~Renderer() = default;

uint64_t Renderer::gbufferBytesPerSample(const Scene& scene) {
  uint64_t bytes = texelBytes(kDepthStencilFormat);
  for (GLenum format : kGBufferFormats) bytes += texelBytes(format);
  return bytes + (writesVelocity(scene) ? texelBytes(kVelocityFormat) : 0);
}

void Renderer::createTargets(int width, int height) {
  color_ = makeTexture2D(kGBufferFormats[0], width, height, "host.gbuffer.color");
  position_ = makeTexture2D(kGBufferFormats[1], width, height, "host.gbuffer.position");
  normal_ = makeTexture2D(kGBufferFormats[2], width, height, "host.gbuffer.normal");
  specular_ = makeTexture2D(kGBufferFormats[3], width, height, "host.gbuffer.specular");
  emissive_ = makeTexture2D(kGBufferFormats[4], width, height, "host.gbuffer.emissive");
  depthStencil_ = makeTexture2D(kDepthStencilFormat, width, height, "host.gbuffer.depth_stencil");
  light_ = makeTexture2D(GL_RGBA16F, width, height, "host.light");
  display_ = makeTexture2D(GL_RGBA8, width, height, "host.display");
  // Objects that move on their own: the model pass writes their motion too (engines with TAA do).
  velocity_ =
      writesVelocity(scene_) ? makeTexture2D(kVelocityFormat, width, height, "host.gbuffer.velocity") : Texture();

  GLuint fbos[3];
  glCreateFramebuffers(3, fbos);
  gbufferFramebuffer_ = Framebuffer(fbos[0]);
  lightFramebuffer_ = Framebuffer(fbos[1]);
  displayFramebuffer_ = Framebuffer(fbos[2]);
  const GLuint attachments[] = {color_, position_, normal_, specular_, emissive_, velocity_};
  const int attachmentCount = writesVelocity(scene_) ? 6 : 5;
  GLenum drawBuffers[6];
  for (int i = 0; i < attachmentCount; ++i) {
    glNamedFramebufferTexture(gbufferFramebuffer_, GL_COLOR_ATTACHMENT0 + i, attachments[i], 0);
    drawBuffers[i] = GL_COLOR_ATTACHMENT0 + i;
  }
  glNamedFramebufferDrawBuffers(gbufferFramebuffer_, attachmentCount, drawBuffers);
  glNamedFramebufferTexture(gbufferFramebuffer_, GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_, 0);
  glNamedFramebufferTexture(lightFramebuffer_, GL_COLOR_ATTACHMENT0, light_, 0);
  glNamedFramebufferTexture(displayFramebuffer_, GL_COLOR_ATTACHMENT0, display_, 0);
  glObjectLabel(GL_FRAMEBUFFER, gbufferFramebuffer_, -1, "host.gbuffer");
  glObjectLabel(GL_FRAMEBUFFER, lightFramebuffer_, -1, "host.light");
  glObjectLabel(GL_FRAMEBUFFER, displayFramebuffer_, -1, "host.display");
  checkFramebuffer(gbufferFramebuffer_, "host.gbuffer");
  checkFramebuffer(lightFramebuffer_, "host.light");
  checkFramebuffer(displayFramebuffer_, "host.display");

  targets_ = HostTargets{width,
                         height,
                         gbufferFramebuffer_,
                         color_,
                         position_,
                         normal_,
                         specular_,
                         emissive_,
                         depthStencil_,
                         velocity_,
                         lightFramebuffer_,
                         light_,
                         displayFramebuffer_,
                         display_,
                         scene_.depthBuffer == DepthBuffer::Logarithmic,
                         scene_.positionDepth == PositionDepth::FsoCompressed,
                         scene_.camera.farPlane};
  hooks_->targetsCreated(targets_);
}

void Renderer::resize(int width, int height) {
  if (width == targets_.width && height == targets_.height) return;
  createTargets(width, height);
}

void Renderer::setHooks(FrameHooks* hooks) {
  hooks_ = hooks ? hooks : &stockHooks_;
  hooks_->targetsCreated(targets_);
}

void Renderer::setStockPath(bool stock) {
  if (stock == (suspendedHooks_ != nullptr)) return;
  FrameHooks* installed = stock ? hooks_ : suspendedHooks_;
  suspendedHooks_ = stock ? hooks_ : nullptr;
  setHooks(stock ? nullptr : installed);
}

void Renderer::renderFrame(const Camera& camera, glm::vec2 jitterPixels) {
  const int width = targets_.width, height = targets_.height;
  const glm::mat4 view = camera.view();
  const glm::mat4 projection = camera.projection(width, height, jitterPixels + hooks_->projectionJitter());
  // The velocity attachment's two frames, without jitter (the first frame: no motion).
  const glm::mat4 viewProjection = camera.projection(width, height) * view;
  motion_.previous = hasPrevious_ ? motion_.current : viewProjection;
  motion_.previousTime = hasPrevious_ ? motion_.currentTime : camera.time;
  motion_.current = viewProjection, motion_.currentTime = camera.time, hasPrevious_ = true;
  applyTextureLodBias(hooks_->textureLodBias());
  StageTimestamps stages(measureTime);
  stages.stamp(StageTimestamps::FrameStart);

  // gr_opengl_scene_texture_begin() + gr_opengl_deferred_lighting_begin()
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 1, -1, "host.model_pass");
  const GLuint modelTarget = hooks_->modelPassFramebuffer(gbufferFramebuffer_);
  const int modelScale = hooks_->modelPassScale();
  glBindFramebuffer(GL_FRAMEBUFFER, modelTarget);
  glViewport(0, 0, width * modelScale, height * modelScale);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i < attachmentCount(); ++i) glClearNamedFramebufferfv(modelTarget, GL_COLOR, i, zero);
  glClearNamedFramebufferfi(modelTarget, GL_DEPTH_STENCIL, 0, 1.0f, 0);

  drawBackground(view, projection, glm::vec2(width, height) * float(modelScale));
  drawModels(camera, projection);
  glPopDebugGroup();
  stages.stamp(StageTimestamps::ModelPassEnd);

  // gr_opengl_deferred_lighting_msaa() + gr_opengl_deferred_lighting_end()
  FrameView frameView;
  frameView.verticalFovRadians = glm::radians(camera.fovYDegrees);
  frameView.width = width;
  frameView.height = height;
  frameView.nearPlane = camera.nearPlane;
  frameView.farPlane = camera.farPlane;
  frameView.view = view;
  frameView.projection = camera.projection(width, height, jitterPixels);
  if (scene_.objectMotion == Scene::ObjectMotion::Boxes) frameView.movingBoxes = movingBoxes();
  hooks_->modelPassEnd(frameView);
  hooks_->modelPrepass([&](GLuint target) { drawPrepass(target, camera, projection); });
  stages.stamp(StageTimestamps::HooksEnd);

  // gr_opengl_deferred_lighting_finish()
  hooks_->lighting([&](GLuint target) { lightingPass(target, camera, projection); }, lightFramebuffer_);
  stages.stamp(StageTimestamps::LightingEnd);

  // gr_opengl_post_process_end(): tonemap, then the AA post pass.
  tonemap(light_);
  hooks_->postProcess();
  stages.stamp(StageTimestamps::FrameEnd);
  stages.readInto(timings_);
}

// The sky goes into emissive first (FSO copies what was drawn before the models there).
void Renderer::drawBackground(const glm::mat4& view, const glm::mat4& projection, glm::vec2 viewportSize) {
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glUseProgram(backgroundProgram_.get());
  setUniform(backgroundProgram_.uniform("uInverseProjection"), glm::inverse(projection));
  setUniform(backgroundProgram_.uniform("uViewToWorld"), glm::mat3(glm::inverse(view)));
  setUniform(backgroundProgram_.uniform("uViewportSize"), viewportSize);
  setUniform(backgroundProgram_.uniform("uSkyColor"), scene_.skyColor);
  setUniform(backgroundProgram_.uniform("uStarDensity"), backgroundDetailOn_ ? scene_.starDensity : 0.0f);
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The models once more into the AA module's prepass target.
void Renderer::drawPrepass(GLuint target, const Camera& camera, const glm::mat4& projection) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 4, -1, "host.model_prepass");
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, targets_.width, targets_.height);
  glDepthMask(GL_TRUE);
  // Draw buffers the target leaves GL_NONE ignore both the clear and the writes.
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i < attachmentCount(); ++i) glClearNamedFramebufferfv(target, GL_COLOR, i, zero);
  glClearNamedFramebufferfi(target, GL_DEPTH_STENCIL, 0, 1.0f, 0);
  drawModels(camera, projection);
  glPopDebugGroup();
}

void Renderer::drawModels(const Camera& camera, const glm::mat4& projection) {
  const glm::mat4 view = camera.view();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glUseProgram(modelProgram_.get());
  setUniform(modelProgram_.uniform("uProjection"), projection);
  setUniform(modelProgram_.uniform("uNear"), camera.nearPlane);
  setUniform(modelProgram_.uniform("uFar"), camera.farPlane);
  setUniform(modelProgram_.uniform("uViewportPixels"), glm::vec2(targets_.width, targets_.height));
  for (size_t i = 0; i < scene_.objects.size(); ++i) {
    const Object& object = scene_.objects[i];
    const Material& material = scene_.materials[object.material];
    const glm::mat4 modelView = view * object.transformAt(camera.time);
    setUniform(modelProgram_.uniform("uModelView"), modelView);
    setUniform(modelProgram_.uniform("uCurrentClip"), motion_.current * object.transformAt(motion_.currentTime));
    setUniform(modelProgram_.uniform("uPreviousClip"), motion_.previous * object.transformAt(motion_.previousTime));
    setUniform(modelProgram_.uniform("uNormalMatrix"), glm::transpose(glm::inverse(glm::mat3(modelView))));
    setUniform(modelProgram_.uniform("uAlbedo"), material.albedo);
    setUniform(modelProgram_.uniform("uSpecular"), material.specular);
    setUniform(modelProgram_.uniform("uGloss"), material.gloss);
    setUniform(modelProgram_.uniform("uEmissive"), material.emissive);
    setUniform(modelProgram_.uniform("uUvScale"), material.maps.uvScale);
    setUniform(modelProgram_.uniform("uNormalMapped"),
               materialTextures_->normalMapped(size_t(object.material)) ? 1 : 0);
    materialTextures_->bind(size_t(object.material));
    glBindVertexArray(meshes_[i].vertexArray);
    glDrawElements(GL_TRIANGLES, meshes_[i].indexCount, GL_UNSIGNED_INT, nullptr);
  }
  materialTextures_->unbind();
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
}

void Renderer::lightingPass(GLuint target, const Camera& camera, const glm::mat4& projection) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 2, -1, "host.lighting");
  const glm::mat4 view = camera.view();
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, targets_.width, targets_.height);
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(target, GL_COLOR, 0, zero);
  const GLuint gbuffer[] = {color_, position_, normal_, specular_, emissive_};
  glBindTextures(0, 5, gbuffer);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindVertexArray(emptyVertexArray_);

  // Ambient and directional lights: one full-screen pass.
  glUseProgram(ambientProgram_.get());
  setUniform(ambientProgram_.uniform("uShadingModel"), scene_.shading == ShadingModel::GGX ? 1 : 0);
  setUniform(ambientProgram_.uniform("uAmbient"), scene_.ambient);
  int directional = 0;
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::Directional || directional == 4) continue;
    const glm::vec3 toLight = glm::normalize(glm::mat3(view) * -light.direction);
    const std::string index = "[" + std::to_string(directional) + "]";
    setUniform(ambientProgram_.uniform(("uToLight" + index).c_str()), toLight);
    setUniform(ambientProgram_.uniform(("uRadiance" + index).c_str()), light.color * light.intensity);
    ++directional;
  }
  setUniform(ambientProgram_.uniform("uDirectionalCount"), directional);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  // Point and tube lights as volumes; back faces only, so a camera inside a volume still lights.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glUseProgram(pointProgram_.get());
  setUniform(pointProgram_.uniform("uShadingModel"), scene_.shading == ShadingModel::GGX ? 1 : 0);
  setUniform(pointProgram_.uniform("uProjection"), projection);
  for (const Light& light : scene_.lights) {
    if (light.type == LightType::Directional) continue;
    const glm::vec3 start = glm::vec3(view * glm::vec4(light.position, 1.0f));
    const glm::vec3 end = glm::vec3(view * glm::vec4(light.end, 1.0f));
    setUniform(pointProgram_.uniform("uStart"), start);
    setUniform(pointProgram_.uniform("uEnd"), end);
    setUniform(pointProgram_.uniform("uRadiance"), light.color * light.intensity);
    setUniform(pointProgram_.uniform("uRadius"), light.radius);
    glm::mat4 volume;
    const GpuMesh* mesh = &sphereVolume_;
    if (light.type == LightType::Point) {
      volume = glm::scale(glm::translate(glm::mat4(1.0f), start), glm::vec3(light.radius * 1.1f));
    } else {
      // The tube's view-space bounding box, grown by the radius (the unit box spans [-1, 1]).
      const glm::vec3 centre = (start + end) * 0.5f;
      const glm::vec3 half = glm::abs(end - start) * 0.5f + light.radius;
      volume = glm::scale(glm::translate(glm::mat4(1.0f), centre), half);
      mesh = &boxVolume_;
    }
    setUniform(pointProgram_.uniform("uVolumeToView"), volume);
    glBindVertexArray(mesh->vertexArray);
    glDrawElements(GL_TRIANGLES, mesh->indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_CULL_FACE);

  // Emissive (and the sky) last.
  glUseProgram(emissiveProgram_.get());
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glPopDebugGroup();
}

void Renderer::lightGBuffer(const Camera& camera, GLuint target) {
  lightingPass(target, camera, camera.projection(targets_.width, targets_.height));
}

void Renderer::tonemap(GLuint hdrTexture) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 3, -1, "host.tonemap");
  glBindFramebuffer(GL_FRAMEBUFFER, displayFramebuffer_);
  glViewport(0, 0, targets_.width, targets_.height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(tonemapProgram_.get());
  setUniform(tonemapProgram_.uniform("uExposure"), scene_.exposure);
  glBindTextureUnit(0, hdrTexture);
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glPopDebugGroup();
}

std::vector<uint8_t> Renderer::readDisplay() const {
  return readTopDown<uint8_t>(display_, targets_.width, targets_.height, GL_UNSIGNED_BYTE);
}

std::vector<float> Renderer::readLight() const {
  return readTopDown<float>(light_, targets_.width, targets_.height, GL_FLOAT);
}

}  // namespace host
