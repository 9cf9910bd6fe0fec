#include "test_support.h"

#include "commands.h"

#include <glm/gtc/matrix_transform.hpp>

namespace testing_support {

host::HeadlessContext& context() {
  static host::HeadlessContext instance;
  return instance;
}

std::string testDataPath(const std::string& relative) { return std::string(RETROAA_TEST_DATA) + "/" + relative; }

PatchedHost::PatchedHost(const std::string& scenePath, int width, int height) : scene(host::loadScene(scenePath)) {
  context();
  renderer = std::make_unique<host::Renderer>(scene, width, height);
  auto created = patch::RetroaaHooks::create(renderer->targets(), retroaa::Config{});
  if (!created) throw std::runtime_error(created.error().message);
  hooks = std::move(created.value());
  renderer->setHooks(hooks.get());
}

app::DisplayImage PatchedHost::render(const std::string& methodSpec, const retroaa::Config& base) {
  const retroaa::Status status = hooks->plugin().reconfigure(app::parseMethodSpec(methodSpec, base).config);
  if (!status) throw std::runtime_error(status.error().message);
  renderer->renderFrame(scene.camera);
  return app::DisplayImage::fromRgba8(renderer->width(), renderer->height(), renderer->readDisplay());
}

host::GroundTruth PatchedHost::groundTruth(int samplesPerAxis) {
  return host::renderGroundTruth(*renderer, scene.camera, samplesPerAxis);
}

glm::ivec2 projectToPixel(const host::Camera& camera, glm::vec3 world, int width, int height) {
  const glm::vec4 clip = camera.projection(width, height) * camera.view() * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const int x = static_cast<int>((ndc.x * 0.5f + 0.5f) * width);
  const int yUp = static_cast<int>((ndc.y * 0.5f + 0.5f) * height);
  return {x, height - 1 - yUp};
}

}  // namespace testing_support
