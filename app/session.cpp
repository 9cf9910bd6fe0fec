#include "session.h"

#include "renderer.h"
#include "retroaa/config.h"
#include "retroaa/plugin.h"

#include <algorithm>
#include <cstdio>

namespace app {

namespace {
template <typename Hooks, typename Created>
std::unique_ptr<Hooks> attach(Created created) {
  if (!created) throw std::runtime_error("retroaa: " + created.error().message);
  return std::move(created.value());
}

// The plugin's budget for the multisampled (or supersampled) mirror of the host's G-buffer, applied to `config`
// before the host's own targets exist: at 8192 x 8192 they alone take gigabytes, which the plugin's own check,
// made once they exist, comes too late to spare.
void requireGBufferWithinBudget(uint64_t bytesPerSample, int width, int height, const retroaa::Config& config) {
  const retroaa::MethodInfo* method = retroaa::findMethod(config.method);
  if (!method || !retroaa::usesMsaa(config.method)) return;
  GLint maxSamples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  const int factor = std::max(config.supersample, 2);  // a supersampled G-buffer: factor² sub-positions
  const uint64_t samples = method->multisampled ? uint64_t(std::clamp(config.samples, 1, std::max(int(maxSamples), 1)))
                                                : uint64_t(factor) * uint64_t(factor);
  const uint64_t bytes = bytesPerSample * uint64_t(width) * uint64_t(height) * samples;
  const uint64_t budget = retroaa::Description{}.gbufferBudgetBytes;
  if (budget == 0 || bytes <= budget) return;
  char size[200];
  std::snprintf(size, sizeof size, "%d x %d x %llu samples x %llu B = %.2f GiB", width, height,
                static_cast<unsigned long long>(samples), static_cast<unsigned long long>(bytesPerSample),
                double(bytes) / double(1ull << 30));
  throw std::invalid_argument(std::string(method->name) + ": the MSAA G-buffer would take " + size +
                              ", over its budget of " + std::to_string(budget >> 20) +
                              " MiB: ask for fewer samples or a smaller size");
}

// The hosts a session renders through, by the name `--host` takes: what one sample of each one's G-buffer
// takes, and how its engine is built with its patch attached.
struct HostRow {
  const char* name;
  uint64_t (*gbufferBytesPerSample)(const host::Scene&);
  void (*build)(Session&, int width, int height);
};
const HostRow kHosts[] = {
    {"fso", [](const host::Scene& scene) { return host::Renderer::gbufferBytesPerSample(scene); },
     [](Session& session, int width, int height) {
       auto engine = std::make_unique<host::Renderer>(session.scene, width, height);
       session.fsoHooks = attach<patch::RetroaaHooks>(patch::RetroaaHooks::create(engine->targets(), {}));
       engine->setHooks(session.fsoHooks.get());
       session.renderer = std::move(engine);
     }},
    {"second", [](const host::Scene&) { return host::SecondRenderer::gbufferBytesPerSample(); },
     [](Session& session, int width, int height) {
       auto engine = std::make_unique<host::SecondRenderer>(session.scene, width, height);
       session.secondHooks = attach<patch::SecondHostHooks>(patch::SecondHostHooks::create(engine->targets(), {}));
       engine->setSeams(session.secondHooks.get());
       session.renderer = std::move(engine);
     }},
};

}  // namespace

std::vector<std::string> hostNames() {
  std::vector<std::string> names;
  for (const HostRow& row : kHosts) names.push_back(row.name);
  return names;
}

Session::Session(const std::string& scenePath, int width, int height, std::string contextSummary,
                 const std::string& hostName, const std::vector<retroaa::Config>& configsToRun)
    : scene(host::loadScene(scenePath)), hostName(hostName), contextSummary(std::move(contextSummary)) {
  const auto row =
      std::find_if(std::begin(kHosts), std::end(kHosts), [&hostName](const HostRow& r) { return hostName == r.name; });
  if (row == std::end(kHosts)) {
    std::string allowed;
    for (const std::string& name : hostNames()) allowed += (allowed.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown host '" + hostName + "' (allowed: " + allowed + ")");
  }
  const uint64_t bytesPerSample = row->gbufferBytesPerSample(scene);
  for (const retroaa::Config& config : configsToRun) requireGBufferWithinBudget(bytesPerSample, width, height, config);
  row->build(*this, width, height);
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
