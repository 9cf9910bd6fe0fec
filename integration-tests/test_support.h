// Shared by the integration tests: one headless context per test process, and helpers to render
// the built-in scenes through the host with the engine patch.
#pragma once

#include "ground_truth.h"
#include "headless_context.h"
#include "metrics.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace testing_support {

// Created on first use, lives until the process exits.
host::HeadlessContext& context();

// Path of a file in integration-tests/ (scenes, fixtures).
std::string testDataPath(const std::string& relative);

// A host renderer on a scene with the retroaa patch installed.
struct PatchedHost {
  host::Scene scene;
  std::unique_ptr<host::Renderer> renderer;
  std::unique_ptr<patch::RetroaaHooks> hooks;
  PatchedHost(const std::string& scenePath, int width, int height);
  // Renders the scene camera with a method spec (see app::parseMethodSpec) and returns the display.
  app::DisplayImage render(const std::string& methodSpec, const retroaa::Config& base = {});
  host::GroundTruth groundTruth(int samplesPerAxis);
};

// The pixel (top-down image coordinates) where a world point lands for the scene camera.
glm::ivec2 projectToPixel(const host::Camera& camera, glm::vec3 world, int width, int height);

}  // namespace testing_support
