#include "viewer.h"

#include "commands.h"
#include "ground_truth.h"
#include "image_io.h"
#include "metrics.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"
#include "session.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <sstream>

namespace app {

namespace {

int glErrors = 0;
void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                               const void*) {
  if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH) {
    ++glErrors;
    std::fprintf(stderr, "GL debug: %s\n", message);
  }
}

struct ScriptAction {
  int frame;
  std::string verb;
  std::vector<std::string> arguments;
  int line;
};

std::vector<ScriptAction> readScript(const std::string& path) {
  std::string problem;
  const std::optional<std::string> content = host::readUserTextFile(path, problem);
  if (!content) throw std::invalid_argument(path + ": cannot open script: " + problem);
  std::istringstream in(*content);
  std::vector<ScriptAction> actions;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    std::istringstream words(text);
    ScriptAction action{0, "", {}, line};
    if (!(words >> action.frame)) continue;
    if (!(words >> action.verb))
      throw std::invalid_argument(path + ":" + std::to_string(line) + ": expected 'FRAME ACTION [ARGUMENTS]'");
    for (std::string word; words >> word;) action.arguments.push_back(word);
    actions.push_back(action);
  }
  return actions;
}

float number(const ScriptAction& a, size_t i, const std::string& path) {
  if (i >= a.arguments.size())
    throw std::invalid_argument(path + ":" + std::to_string(a.line) + ": '" + a.verb + "' needs more arguments");
  try {
    return std::stof(a.arguments[i]);
  } catch (const std::exception&) {
    throw std::invalid_argument(path + ":" + std::to_string(a.line) + ": '" + a.arguments[i] + "' is not a number");
  }
}

std::vector<uint8_t> readWindow(int width, int height) {
  std::vector<uint8_t> pixels(size_t(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  std::vector<uint8_t> flipped(pixels.size());  // GL rows bottom-up, images top-down
  for (int y = 0; y < height; ++y)
    std::copy_n(&pixels[size_t(height - 1 - y) * width * 4], width * 4, &flipped[size_t(y) * width * 4]);
  return flipped;
}

// The viewer: two sides (A, and B when split), the fly camera, the script, the panel. One frame of
// the loop runs the steps below in order.
class Viewer {
 public:
  Viewer(const ViewOptions& options, GLFWwindow* window) : options_(options), window_(window) {
    glfwGetFramebufferSize(window_, &width_, &height_);
    contextSummary_ = std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + " | " +
                      reinterpret_cast<const char*>(glGetString(GL_VERSION)) + " | GLFW window";
    a_ = makeSide("off");
    objectsAtStart_ = a_->plugin().stats().glObjectsHeld;  // compared with `off` at the end
    configureSpec(*a_, options_.method);
    if (!options_.compare.empty()) b_ = makeSide(options_.compare);
    if (!options_.script.empty()) script_ = readScript(options_.script);
    methods_ = expandMethodList("all");
    magnifierAt_ = {width_ / 2.0f, height_ / 2.0f};
    setCamera(a_->scene.camera);
  }

  int run() {
    int status = kExitOk;
    for (int frame = 0; !quit_ && !glfwWindowShouldClose(window_); ++frame) {
      const auto frameStart = std::chrono::steady_clock::now();
      glfwPollEvents();
      screenshot_.clear(), screenshotWithPanel_.clear();
      for (; nextAction_ < script_.size() && script_[nextAction_].frame <= frame; ++nextAction_)
        runAction(script_[nextAction_]);
      followWindowSize();
      if (options_.script.empty() && !ImGui::GetIO().WantCaptureKeyboard) handleInput(frame);
      renderAndCompose();
      if (!screenshot_.empty()) writeScreenshot(screenshot_);
      drawPanel();
      if (!screenshotWithPanel_.empty()) {
        writeImage8(screenshotWithPanel_, width_, height_, readWindow(width_, height_),
                    {{"retroaa:method", a_->method}});
        std::printf("view: screenshot with the panel %s\n", screenshotWithPanel_.c_str());
      }
      glfwSwapBuffers(window_);
      recordFrameTime(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
      if (!a_->lastError().empty()) {
        std::fprintf(stderr, "view: plugin error: %s\n", a_->lastError().c_str());
        status = kExitCheckFailed;
        break;
      }
    }
    std::printf("view: %zu frames timed, median frame %.1f ms (CPU wall time: host, plugin, panel and swap)\n",
                frameMs_.size(), medianFrameMs());
    configureSpec(*a_, "off");
    a_->renderer->renderFrame(camera_);
    const int objectsAtEnd = a_->plugin().stats().glObjectsHeld;
    std::printf("view: %d GL errors; plugin GL objects %d at start, %d at the end (method off)\n", glErrors,
                objectsAtStart_, objectsAtEnd);
    if (glErrors > 0 || objectsAtEnd != objectsAtStart_) status = kExitCheckFailed;
    return status;
  }

 private:
  static constexpr double kTimeStep = 1.0 / 30.0;  // scripted runs and path playback use a fixed step

  // The last second or so of frame times (CPU wall clock), for the overlay and the closing line.
  void recordFrameTime(double ms) {
    frameMs_.push_back(ms);
    if (frameMs_.size() > 60) frameMs_.erase(frameMs_.begin());
  }
  double medianFrameMs() const {
    if (frameMs_.empty()) return 0;
    std::vector<double> sorted = frameMs_;
    std::sort(sorted.begin(), sorted.end());
    return sorted[sorted.size() / 2];
  }

  std::unique_ptr<Session> makeSide(const std::string& spec) {
    auto side = std::make_unique<Session>(options_.scene, width_, height_, contextSummary_);
    configureSpec(*side, spec);
    return side;
  }
  // Every side times its passes for the panel.
  void configure(Session& side, retroaa::Config config, const std::string& spec) {
    config.measureGpuTime = true;
    side.configure(config, spec);
  }
  void configureSpec(Session& side, const std::string& spec) {
    configure(side, parseMethodSpec(spec, options_.base).config, spec);
  }
  // The next of a key's values (samples, resolve_weighting, edge_detector), after the current one.
  void cycle(const std::string& key) {
    const std::vector<std::string> values = retroaa::settingValues(key);
    const auto at = std::find(values.begin(), values.end(), retroaa::readSetting(a_->config, key));
    retroaa::Config config = a_->config;
    if (retroaa::applySetting(config, key, values[at == values.end() ? 0 : (at - values.begin() + 1) % values.size()]))
      configure(*a_, config, a_->method);
  }
  void setCamera(const host::Camera& camera) {
    camera_ = camera;
    const glm::vec3 forward = glm::normalize(camera_.target - camera_.position);
    yaw_ = std::atan2(forward.x, -forward.z), pitch_ = std::asin(forward.y);
  }

  void runAction(const ScriptAction& act) {
    const auto& args = act.arguments;
    const std::string& path = options_.script;
    auto need = [&](size_t n) {
      if (args.size() < n)
        throw std::invalid_argument(path + ":" + std::to_string(act.line) + ": '" + act.verb + "' needs " +
                                    std::to_string(n) + " arguments");
    };
    auto at = [&](size_t i) { return number(act, i, path); };
    if (act.verb == "method")
      need(1), configureSpec(*a_, args[0]);
    else if (act.verb == "compare") {
      need(1);
      if (args[0] == "off-split")
        b_.reset();
      else if (b_)
        configureSpec(*b_, args[0]);
      else
        b_ = makeSide(args[0]);
    } else if (act.verb == "set") {
      need(2);
      for (Session* side : {a_.get(), b_.get()}) {
        if (!side) continue;
        retroaa::Config config = side->config;
        const retroaa::Status s = retroaa::applySetting(config, args[0], args[1]);
        if (!s) throw std::invalid_argument(path + ":" + std::to_string(act.line) + ": " + s.error().message);
        configure(*side, config, side->method);
      }
    } else if (act.verb == "camera") {
      need(6);
      host::Camera camera = camera_;
      camera.position = {at(0), at(1), at(2)};
      camera.target = {at(3), at(4), at(5)};
      setCamera(camera);
    } else if (act.verb == "path")
      need(1), pathFrame_ = int(at(0)), camera_ = a_->scene.path.at(a_->scene.camera, pathFrame_);
    else if (act.verb == "resize")
      need(2), glfwSetWindowSize(window_, int(at(0)), int(at(1)));
    else if (act.verb == "divider")
      need(1), divider_ = at(0);
    else if (act.verb == "magnifier") {
      need(1);
      magnifier_ = args[0] != "off";
      if (magnifier_) need(3), magnifierAt_ = {at(0), at(1)}, magnifierZoom_ = int(at(2));
    } else if (act.verb == "screenshot")
      need(1), screenshot_ = args[0];
    else if (act.verb == "screenshot-panel")
      need(1), screenshotWithPanel_ = args[0];
    else if (act.verb == "quit")
      quit_ = true;
    else
      throw std::invalid_argument(path + ":" + std::to_string(act.line) + ": unknown action '" + act.verb +
                                  "' (allowed: method, compare, set, camera, path, resize, divider, magnifier, "
                                  "screenshot, screenshot-panel, quit)");
  }

  // The window's size is the renderers' size; the plugin reallocates through the engine patch.
  void followWindowSize() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width <= 0 || height <= 0 || (width == width_ && height == height_)) return;
    width_ = width, height_ = height;
    a_->renderer->resize(width_, height_);
    if (b_) b_->renderer->resize(width_, height_);
  }

  // GLFW keys (ImGui 1.86's key enum lacks letters): held, and pressed since the last frame.
  bool down(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }
  bool pressed(int key) {
    const bool now = down(key), before = wasDown_[key];
    wasDown_[key] = now;
    return now && !before;
  }

  // Fly camera (interactive only): WASD, right mouse to look, wheel for speed; P plays the path.
  void handleInput(int frame) {
    ImGuiIO& io = ImGui::GetIO();
    const glm::vec3 forward(std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_));
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    glm::vec3 move(0);
    if (down(GLFW_KEY_W)) move += forward;
    if (down(GLFW_KEY_S)) move -= forward;
    if (down(GLFW_KEY_D)) move += right;
    if (down(GLFW_KEY_A)) move -= right;
    if (!io.WantCaptureMouse) {
      if (ImGui::IsMouseDown(ImGuiMouseButton_Right))
        yaw_ += io.MouseDelta.x * 0.004f, pitch_ = glm::clamp(pitch_ - io.MouseDelta.y * 0.004f, -1.5f, 1.5f);
      speed_ *= std::pow(1.25f, io.MouseWheel);  // 10 m and 50 km are both a few wheel turns away
      if (b_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) divider_ = glm::clamp(io.MousePos.x / width_, 0.0f, 1.0f);
      magnifierAt_ = {io.MousePos.x, io.MousePos.y};
    }
    if (pressed(GLFW_KEY_P)) playing_ = !playing_;
    if (pressed(GLFW_KEY_Z)) magnifier_ = !magnifier_;
    if (pressed(GLFW_KEY_M)) {
      const auto at = std::find(methods_.begin(), methods_.end(), a_->method);
      configureSpec(*a_, methods_[at == methods_.end() ? 0 : (at - methods_.begin() + 1) % methods_.size()]);
    }
    if (pressed(GLFW_KEY_F12)) screenshot_ = "retroaa-screenshot.png";
    if (pressed(GLFW_KEY_N)) cycle("samples");
    if (pressed(GLFW_KEY_B)) cycle("resolve_weighting");
    if (pressed(GLFW_KEY_E)) cycle("edge_detector");
    if (pressed(GLFW_KEY_R)) toggleRecording();
    camera_.position += move * speed_ * float(kTimeStep);
    camera_.target = camera_.position + forward;
    const host::Scene& scene = a_->scene;
    if (playing_) camera_ = scene.path.at(scene.camera, pathFrame_++ % std::max(scene.path.frameCount(), 1));
    if (recording_ && frame % 8 == 0)
      recorded_.push_back({float(recorded_.size() * 8 * kTimeStep), camera_.position, camera_.target});
    if (pressed(GLFW_KEY_G)) measureAgainstGroundTruth();
  }

  void toggleRecording() {
    recording_ = !recording_;
    if (!recording_ && recorded_.size() >= 2) {
      nlohmann::json keys = nlohmann::json::array();
      for (const auto& k : recorded_)
        keys.push_back({{"t", k.time},
                        {"position", {k.position.x, k.position.y, k.position.z}},
                        {"target", {k.target.x, k.target.y, k.target.z}}});
      std::ofstream(options_.recordPath) << nlohmann::json{{"fps", 30}, {"keys", keys}}.dump(1) << "\n";
      std::printf("view: recorded %zu keys to %s\n", recorded_.size(), options_.recordPath.c_str());
    }
    if (recording_) recorded_.clear();
  }

  void measureAgainstGroundTruth() {
    const host::GroundTruth truth = host::renderGroundTruth(*a_->renderer, camera_, 8);
    a_->renderer->renderFrame(camera_);
    const ErrorMetrics m =
        compare(DisplayImage::fromRgba8(width_, height_, a_->renderer->readDisplay()),
                DisplayImage::fromRgba8(width_, height_, truth.display), edgeMaskFromSpread(truth.lumaStdDev));
    char text[160];
    std::snprintf(text, sizeof text, "%s vs 8×8 ground truth: PSNR %.2f dB, edge PSNR %.2f dB", a_->method.c_str(),
                  m.psnrDb, m.edgePsnrDb);
    groundTruthText_ = text;
  }

  // Both sides through the host's own pipeline, composed into the window.
  void renderAndCompose() {
    a_->renderer->renderFrame(camera_);
    if (b_) b_->renderer->renderFrame(camera_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, width_, height_);
    const int split = b_ ? int(divider_ * width_) : width_;
    const GLuint aDisplay = a_->renderer->displayFramebuffer();
    glBlitNamedFramebuffer(aDisplay, 0, 0, 0, split, height_, 0, 0, split, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (b_) {
      glBlitNamedFramebuffer(b_->renderer->displayFramebuffer(), 0, split, 0, width_, height_, split, 0, width_,
                             height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glEnable(GL_SCISSOR_TEST);  // the divider: a 2-pixel white line
      glScissor(std::max(split - 1, 0), 0, 2, height_);
      glClearColor(1, 1, 1, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
    }
    if (magnifier_) {  // nearest-neighbour zoom of the region under the cursor, in the top-right corner
      const int lens = std::min(width_, height_) / 3, source = std::max(lens / magnifierZoom_, 1);
      const int sx = glm::clamp(int(magnifierAt_.x) - source / 2, 0, width_ - source);
      const int sy = glm::clamp(height_ - int(magnifierAt_.y) - source / 2, 0, height_ - source);
      const GLuint from = (b_ && sx >= split) ? b_->renderer->displayFramebuffer() : aDisplay;
      glBlitNamedFramebuffer(from, 0, sx, sy, sx + source, sy + source, width_ - lens, height_ - lens, width_, height_,
                             GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
  }

  // The composed view without the panel; when split, each side whole as its own method renders it.
  void writeScreenshot(const std::string& path) {
    std::map<std::string, std::string> meta = a_->metadata(a_->method);
    if (b_) meta["retroaa:compare"] = b_->method;
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    writeImage8(path, width_, height_, readWindow(width_, height_), meta);
    std::printf("view: screenshot %s (%dx%d, %s)\n", path.c_str(), width_, height_, a_->method.c_str());
    if (!b_) return;
    const std::string stem = (parent / std::filesystem::path(path).stem()).string();
    writeImage8(stem + "-a.png", width_, height_, a_->renderer->readDisplay(), {{"retroaa:method", a_->method}});
    writeImage8(stem + "-b.png", width_, height_, b_->renderer->readDisplay(), {{"retroaa:method", b_->method}});
  }

  // The widget for one config key, drawn from its description (retroaa::configKeys()): a combo over its
  // values, a checkbox for a switch, a slider over its range (logarithmic where the range is wide).
  bool settingWidget(const std::string& name, retroaa::Config& config) {
    using Kind = retroaa::ConfigKey::Kind;
    const auto& keys = retroaa::configKeys();
    const auto key =
        std::find_if(keys.begin(), keys.end(), [&](const retroaa::ConfigKey& k) { return name == k.name; });
    if (key == keys.end()) return false;
    const std::string current = retroaa::readSetting(config, name);
    std::string chosen;
    if (key->kind == Kind::Switch) {
      bool on = current == "on";
      if (ImGui::Checkbox(key->name, &on)) chosen = on ? "on" : "off";
    } else if (key->kind == Kind::Choice && ImGui::BeginCombo(key->name, current.c_str())) {
      for (const std::string& value : retroaa::settingValues(name))
        if (ImGui::Selectable(value.c_str(), value == current)) chosen = value;
      ImGui::EndCombo();
    } else if (key->kind == Kind::Number) {
      float value = std::stof(current);
      const bool wide = key->maximum >= 100 * std::max(key->minimum, 1.0f);
      if (ImGui::SliderFloat(key->name, &value, key->minimum, key->maximum, "%.3g",
                             wide ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None))
        chosen = std::to_string(value);
    } else if (key->kind == Kind::Integer) {
      int value = std::stoi(current);
      if (ImGui::SliderInt(key->name, &value, int(key->minimum), int(key->maximum))) chosen = std::to_string(value);
    }
    return !chosen.empty() && retroaa::applySetting(config, name, chosen);  // out of range: refused, unchanged
  }

  // The keys the panel shows for `config`: the sample count, the keys the method in use reads, and the
  // switch of every method that stacks on it.
  static std::vector<std::string> panelKeys(const retroaa::Config& config) {
    const std::string method = retroaa::toString(config.method);
    std::vector<std::string> keys = {"samples"};
    for (const retroaa::ConfigKey& key : retroaa::configKeys())
      for (const char* reader : key.methods)
        if (reader == method) keys.push_back(key.name);
    for (const retroaa::MethodInfo& row : retroaa::methodTable())
      if (*row.stackKey && row.name != method) keys.push_back(row.stackKey);
    return keys;
  }

  // The panel: method and settings, what they cost, what they buy.
  void drawPanel() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(480, 0), ImVec2(480, 1e6f));  // wide enough for every label
    ImGui::Begin("retroaa", nullptr, ImGuiWindowFlags_AlwaysAutoResize);     // and as tall as its lines
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 12);                        // leave the labels their room
    if (ImGui::BeginCombo("method", a_->method.c_str())) {
      for (const std::string& method : methods_)
        if (ImGui::Selectable(method.c_str(), method == a_->method)) configureSpec(*a_, method);
      ImGui::EndCombo();
    }
    retroaa::Config config = a_->config;
    bool changed = false;
    for (const std::string& key : panelKeys(config)) changed |= settingWidget(key, config);
    changed |= settingInput(config);  // every other key, by name (the config reference lists them)
    if (changed) configure(*a_, config, a_->method);
    drawStats();
    ImGui::PopItemWidth();
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  bool settingInput(retroaa::Config& config) {
    if (ImGui::InputText("key=value", setting_, sizeof setting_, ImGuiInputTextFlags_EnterReturnsTrue)) {
      const std::string text = setting_;
      const size_t equals = text.find('=');
      const retroaa::Status s =
          equals == std::string::npos
              ? retroaa::Status(retroaa::Error{retroaa::ErrorCode::InvalidConfig, "expected key=value"})
              : retroaa::applySetting(config, text.substr(0, equals), text.substr(equals + 1));
      settingError_ = s ? "" : s.error().message;
      if (s) return true;
    }
    if (!settingError_.empty()) ImGui::TextWrapped("%s", settingError_.c_str());
    return false;
  }

  void drawStats() {
    const retroaa::Stats stats = a_->plugin().stats();
    ImGui::Separator();
    double pluginMs = 0;
    for (const retroaa::PassStats& pass : stats.passes) pluginMs += pass.ms;
    ImGui::TextWrapped("frame %.1f ms CPU wall (median of %zu); plugin passes %.2f ms GPU", medianFrameMs(),
                       frameMs_.size(), pluginMs);
    ImGui::Text("%d×%d, %d samples, %.3f lighting evaluations/pixel", width_, height_, stats.samples,
                stats.evaluationsPerPixel());
    ImGui::Text("plugin memory %.1f MiB (%.0f B/px), %d GL objects", stats.bytesHeld / 1048576.0,
                double(stats.bytesHeld) / (double(width_) * height_), stats.glObjectsHeld);
    std::map<std::string, double> passTotals;  // a pass runs once per slice: one line each
    for (const retroaa::PassStats& pass : stats.passes) passTotals[pass.name] += pass.ms;
    for (const auto& [name, ms] : passTotals) ImGui::Text("  %s: %.2f ms", name.c_str(), ms);
    ImGui::TextWrapped("%s", groundTruthText_.c_str());
    ImGui::TextWrapped(
        "WASD + right mouse: fly; wheel: speed %.1f m/s; P: play path; R: record path%s; M: next method; N/B/E: "
        "samples/weighting/detector; Z: magnifier; G: ground truth; F12: screenshot%s",
        speed_, recording_ ? " (recording)" : "", b_ ? "; left drag: divider" : "");
    if (b_) ImGui::Text("split: %s | %s", a_->method.c_str(), b_->method.c_str());
  }

  const ViewOptions& options_;
  GLFWwindow* window_;
  std::string contextSummary_;
  int width_ = 0, height_ = 0;
  std::unique_ptr<Session> a_, b_;
  int objectsAtStart_ = 0;
  host::Camera camera_;
  std::vector<ScriptAction> script_;
  size_t nextAction_ = 0;
  float divider_ = 0.5f, speed_ = 2.0f, yaw_ = 0, pitch_ = 0;
  bool playing_ = false, magnifier_ = false, recording_ = false, quit_ = false;
  int pathFrame_ = 0, magnifierZoom_ = 8;
  glm::vec2 magnifierAt_{0, 0};
  std::vector<host::CameraKey> recorded_;
  std::string groundTruthText_ = "press G for PSNR against a 8×8 ground truth of this view";
  std::vector<std::string> methods_;
  std::string screenshot_, screenshotWithPanel_;  // this frame's
  std::map<int, bool> wasDown_;
  char setting_[128] = "";
  std::vector<double> frameMs_;
  std::string settingError_;
};

GLFWwindow* openWindow(const ViewOptions& options) {
  if (!glfwInit())
    throw std::runtime_error("GLFW cannot initialise (no display? run under xvfb-run for a virtual one)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "retroaa view", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw std::runtime_error("GLFW cannot create an OpenGL 4.5 core window");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.script.empty() ? 1 : 0);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  return window;
}

void closeWindow(GLFWwindow* window) {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
}

}  // namespace

int runView(const ViewOptions& options) {
  GLFWwindow* window = openWindow(options);
  int status = kExitOk;
  try {
    status = Viewer(options, window).run();
  } catch (...) {
    closeWindow(window);
    throw;
  }
  closeWindow(window);
  return status;
}

}  // namespace app
