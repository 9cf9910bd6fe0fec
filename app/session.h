// One scene rendered through the host with the engine patch installed: what every subcommand
// (render, bench, regress, tune, soak) and each side of the viewer works on.
#pragma once

#include "engine.h"
#include "retroaa_hooks.h"
#include "scene.h"
#include "second_host_patch.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace app {

// The hosts a session can render through (`--host`): the FreeSpace Open-shaped one and the second host.
std::vector<std::string> hostNames();

struct Session {
  host::Scene scene;
  std::string hostName;  // one of hostNames()
  std::unique_ptr<host::Engine> renderer;
  std::unique_ptr<patch::RetroaaHooks> fsoHooks;  // the patch of the host in use: one of these two
  std::unique_ptr<patch::SecondHostHooks> secondHooks;
  std::string contextSummary;  // the GL context (renderer, version, platform), for metadata
  std::string method;          // the spec of the last configure(), as reports name it
  retroaa::Config config;      // the config of the last configure(), as requested

  // Needs a current GL 4.5 core context; throws what loading the scene or creating the plugin throws, and
  // std::invalid_argument for a host not in hostNames() or, before any target exists, for one of
  // `configsToRun` whose multisampled G-buffer would exceed the plugin's budget at this size.
  Session(const std::string& scenePath, int width, int height, std::string contextSummary,
          const std::string& hostName = "fso", const std::vector<retroaa::Config>& configsToRun = {});
  // The scene camera (frame < 0) or frame `frame` of its recorded path.
  host::Camera camera(int frame) const { return frame < 0 ? scene.camera : scene.path.at(scene.camera, frame); }
  retroaa::Plugin& plugin() const { return fsoHooks ? fsoHooks->plugin() : secondHooks->plugin(); }
  // The first error the patch met at a call site (empty: none).
  const std::string& lastError() const { return fsoHooks ? fsoHooks->lastError() : secondHooks->lastError(); }
  // Throws std::invalid_argument with the plugin's message when the config is refused.
  void configure(const retroaa::Config& config, const std::string& methodName = "");
  // Image metadata: method, scene, renderer, the granted config.
  std::map<std::string, std::string> metadata(const std::string& methodName) const;
};

}  // namespace app
