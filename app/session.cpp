#include "session.h"

#include "renderer.h"
#include "retroaa/config.h"

namespace app {

namespace {
template <typename Hooks, typename Created>
std::unique_ptr<Hooks> attach(Created created) {
  if (!created) throw std::runtime_error("retroaa: " + created.error().message);
  return std::move(created.value());
}
}  // namespace

Session::Session(const std::string& scenePath, int width, int height, std::string contextSummary,
                 const std::string& hostName)
    : scene(host::loadScene(scenePath)), hostName(hostName), contextSummary(std::move(contextSummary)) {
  if (hostName == "fso") {
    auto fso = std::make_unique<host::Renderer>(scene, width, height);
    fsoHooks = attach<patch::RetroaaHooks>(patch::RetroaaHooks::create(fso->targets(), retroaa::Config{}));
    fso->setHooks(fsoHooks.get());
    renderer = std::move(fso);
  } else if (hostName == "second") {
    auto second = std::make_unique<host::SecondRenderer>(scene, width, height);
    secondHooks = attach<patch::SecondHostHooks>(patch::SecondHostHooks::create(second->targets(), retroaa::Config{}));
    second->setSeams(secondHooks.get());
    renderer = std::move(second);
  } else {
    throw std::invalid_argument("unknown host '" + hostName + "' (allowed: fso, second)");
  }
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
          {"retroaa:host", hostName},
          {"retroaa:config", retroaa::toConfigText(plugin().config())}};
}

}  // namespace app
