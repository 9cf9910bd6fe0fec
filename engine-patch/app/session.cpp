#include "session.h"

#include "retroaa/config.h"

namespace app {

Session::Session(const std::string& scenePath, int width, int height, std::string contextSummary)
    : scene(host::loadScene(scenePath)), contextSummary(std::move(contextSummary)) {
  renderer = std::make_unique<host::Renderer>(scene, width, height);
  auto created = patch::RetroaaHooks::create(renderer->targets(), retroaa::Config{});
  if (!created) throw std::runtime_error("retroaa: " + created.error().message);
  hooks = std::move(created.value());
  renderer->setHooks(hooks.get());
}

void Session::configure(const retroaa::Config& requested, const std::string& methodName) {
  const retroaa::Status status = plugin().reconfigure(requested);
  if (!status) throw std::invalid_argument(status.error().message);
  config = requested;
  method = methodName.empty() ? retroaa::toString(requested.method) : methodName;
}

std::map<std::string, std::string> Session::metadata(const std::string& methodName) const {
  return {{"retroaa:method", methodName},
          {"retroaa:scene", scene.name},
          {"retroaa:renderer", contextSummary},
          {"retroaa:config", retroaa::toConfigText(plugin().config())}};
}

}  // namespace app
