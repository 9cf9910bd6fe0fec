// `retroaa view`: the interactive viewer (GLFW window, Dear ImGui panel) on the same host engine and
// engine patch as the headless commands — no second rendering path.
#pragma once

#include "retroaa/config.h"

#include <string>

namespace app {

struct ViewOptions {
  std::string scene = "default";
  std::string method = "resolve";  // method A (left, or the whole window)
  std::string compare;             // method B: split screen when set
  retroaa::Config base;
  int width = 960, height = 540;
  std::string script;                             // timed actions, run with a fixed time step (see docs/viewer.md)
  std::string recordPath = "recorded_path.json";  // where R writes the camera path
};

int runView(const ViewOptions& options);

}  // namespace app
