// One scene rendered headless through the host with the engine patch installed: what every
// subcommand (render, bench, regress) works on.
#pragma once

#include "headless_context.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace app {

struct Session {
  const host::HeadlessContext& context;
  host::Scene scene;
  std::unique_ptr<host::Renderer> renderer;
  std::unique_ptr<patch::RetroaaHooks> hooks;

  Session(const host::HeadlessContext& context, const std::string& scenePath, int width, int height);
  // The scene camera (frame < 0) or frame `frame` of its recorded path.
  host::Camera camera(int frame) const { return frame < 0 ? scene.camera : scene.path.at(scene.camera, frame); }
  // Throws std::invalid_argument with the plugin's message when the config is refused.
  void configure(const retroaa::Config& config);
  // Image metadata: method, scene, renderer, the granted config.
  std::map<std::string, std::string> metadata(const std::string& method) const;
};

}  // namespace app
