// One scene rendered through the host with the engine patch installed: what every subcommand
// (render, bench, regress, tune, soak) and each side of the viewer works on.
#pragma once

#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace app {

struct Session {
  host::Scene scene;
  std::unique_ptr<host::Renderer> renderer;
  std::unique_ptr<patch::RetroaaHooks> hooks;
  std::string contextSummary;  // the GL context (renderer, version, platform), for metadata
  std::string method;          // the spec of the last configure(), as reports name it
  retroaa::Config config;      // the config of the last configure(), as requested

  // Needs a current GL 4.5 core context; throws what loading the scene or creating the plugin throws.
  Session(const std::string& scenePath, int width, int height, std::string contextSummary);
  // The scene camera (frame < 0) or frame `frame` of its recorded path.
  host::Camera camera(int frame) const { return frame < 0 ? scene.camera : scene.path.at(scene.camera, frame); }
  retroaa::Plugin& plugin() const { return hooks->plugin(); }
  // Throws std::invalid_argument with the plugin's message when the config is refused.
  void configure(const retroaa::Config& config, const std::string& methodName = "");
  // Image metadata: method, scene, renderer, the granted config.
  std::map<std::string, std::string> metadata(const std::string& methodName) const;
};

}  // namespace app
