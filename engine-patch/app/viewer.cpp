#include "viewer.h"

#include "commands.h"
#include "ground_truth.h"
#include "image_io.h"
#include "metrics.h"
#include "renderer.h"
#include "retroaa_hooks.h"
#include "scene.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <nlohmann/json.hpp>

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
void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message, const void*) {
  if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH) {
    ++glErrors;
    std::fprintf(stderr, "GL debug: %s\n", message);
  }
}

// One side of the view: the host renderer with the engine patch and its plugin.
struct View {
  std::unique_ptr<host::Renderer> renderer;
  std::unique_ptr<patch::RetroaaHooks> hooks;
  std::string method;
  retroaa::Config config;

  View(const host::Scene& scene, int width, int height, const std::string& spec, const retroaa::Config& base) {
    renderer = std::make_unique<host::Renderer>(scene, width, height);
    auto created = patch::RetroaaHooks::create(renderer->targets(), base);
    if (!created) throw std::runtime_error(created.error().message);
    hooks = std::move(created.value());
    renderer->setHooks(hooks.get());
    setMethod(spec, base);
  }
  void setMethod(const std::string& spec, const retroaa::Config& base) {
    config = parseMethodSpec(spec, base).config;
    method = spec;
    apply();
  }
  void apply() {
    config.measureGpuTime = true;
    const retroaa::Status status = hooks->plugin().reconfigure(config);
    if (!status) throw std::invalid_argument(status.error().message);
  }
};

struct ScriptAction {
  int frame;
  std::string verb;
  std::vector<std::string> arguments;
  int line;
};

std::vector<ScriptAction> readScript(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open script");
  std::vector<ScriptAction> actions;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    std::istringstream words(text);
    ScriptAction action{0, "", {}, line};
    if (!(words >> action.frame)) continue;
    if (!(words >> action.verb)) throw std::invalid_argument(path + ":" + std::to_string(line) + ": expected 'FRAME ACTION [ARGUMENTS]'");
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

}  // namespace

int runView(const ViewOptions& options) {
  if (!glfwInit()) throw std::runtime_error("GLFW cannot initialise (no display? run under xvfb-run for a virtual one)");
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

  int status = kExitOk;
  {
    const host::Scene scene = host::loadScene(options.scene);
    host::Camera camera = scene.camera;
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    View a(scene, width, height, "off", options.base);
    const int objectsAtStart = a.hooks->plugin().stats().glObjectsHeld;  // compared with `off` at the end
    a.setMethod(options.method, options.base);
    std::unique_ptr<View> b;
    if (!options.compare.empty()) b = std::make_unique<View>(scene, width, height, options.compare, options.base);
    const std::vector<ScriptAction> script = options.script.empty() ? std::vector<ScriptAction>{} : readScript(options.script);
    size_t nextAction = 0;
    float divider = 0.5f, speed = 2.0f, yaw = 0, pitch = 0;
    bool playing = false, magnifier = false, recording = false, quit = false;
    int pathFrame = 0, magnifierZoom = 8;
    glm::vec2 magnifierAt(width / 2.0f, height / 2.0f);
    std::vector<host::CameraKey> recorded;
    std::string groundTruthText = "press G for PSNR against a 8×8 ground truth of this view";
    const std::vector<std::string> methods = expandMethodList("all");
    {
      const glm::vec3 forward = glm::normalize(camera.target - camera.position);
      yaw = std::atan2(forward.x, -forward.z), pitch = std::asin(forward.y);
    }
    const double timeStep = 1.0 / 30.0;  // scripted runs and path playback use a fixed step
    for (int frame = 0; !quit && !glfwWindowShouldClose(window); ++frame) {
      glfwPollEvents();
      std::string screenshot, screenshotWithPanel;
      // Scripted actions of this frame.
      for (; nextAction < script.size() && script[nextAction].frame <= frame; ++nextAction) {
        const ScriptAction& act = script[nextAction];
        const auto& args = act.arguments;
        auto need = [&](size_t n) {
          if (args.size() < n)
            throw std::invalid_argument(options.script + ":" + std::to_string(act.line) + ": '" + act.verb + "' needs " + std::to_string(n) + " arguments");
        };
        if (act.verb == "method") need(1), a.setMethod(args[0], options.base);
        else if (act.verb == "compare") {
          need(1);
          if (args[0] == "off-split") b.reset();
          else if (b) b->setMethod(args[0], options.base);
          else b = std::make_unique<View>(scene, width, height, args[0], options.base);
        } else if (act.verb == "set") {
          need(2);
          for (View* v : {&a, b.get()}) {
            if (!v) continue;
            const retroaa::Status s = retroaa::applySetting(v->config, args[0], args[1]);
            if (!s) throw std::invalid_argument(options.script + ":" + std::to_string(act.line) + ": " + s.error().message);
            v->apply();
          }
        } else if (act.verb == "camera") {
          need(6);
          camera.position = {number(act, 0, options.script), number(act, 1, options.script), number(act, 2, options.script)};
          camera.target = {number(act, 3, options.script), number(act, 4, options.script), number(act, 5, options.script)};
          const glm::vec3 forward = glm::normalize(camera.target - camera.position);
          yaw = std::atan2(forward.x, -forward.z), pitch = std::asin(forward.y);
        } else if (act.verb == "path") need(1), pathFrame = int(number(act, 0, options.script)), camera = scene.path.at(scene.camera, pathFrame);
        else if (act.verb == "resize") need(2), glfwSetWindowSize(window, int(number(act, 0, options.script)), int(number(act, 1, options.script)));
        else if (act.verb == "divider") need(1), divider = number(act, 0, options.script);
        else if (act.verb == "magnifier") {
          need(1);
          magnifier = args[0] != "off";
          if (magnifier) need(3), magnifierAt = {number(act, 0, options.script), number(act, 1, options.script)}, magnifierZoom = int(number(act, 2, options.script));
        } else if (act.verb == "screenshot") need(1), screenshot = args[0];
        else if (act.verb == "screenshot-panel") need(1), screenshotWithPanel = args[0];
        else if (act.verb == "quit") quit = true;
        else throw std::invalid_argument(options.script + ":" + std::to_string(act.line) + ": unknown action '" + act.verb +
                                         "' (allowed: method, compare, set, camera, path, resize, divider, magnifier, screenshot, screenshot-panel, quit)");
      }
      // The window's size is the renderers' size; the plugin reallocates through the engine patch.
      int newWidth = 0, newHeight = 0;
      glfwGetFramebufferSize(window, &newWidth, &newHeight);
      if (newWidth > 0 && newHeight > 0 && (newWidth != width || newHeight != height)) {
        width = newWidth, height = newHeight;
        a.renderer->resize(width, height);
        if (b) b->renderer->resize(width, height);
      }
      // Fly camera (interactive only): WASD, right mouse to look, wheel for speed; P plays the path.
      ImGuiIO& io = ImGui::GetIO();
      // GLFW keys (ImGui 1.86's key enum lacks letters): held, and pressed since the last frame.
      static std::map<int, bool> wasDown;
      auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
      auto pressed = [&](int key) {
        const bool now = down(key), before = wasDown[key];
        wasDown[key] = now;
        return now && !before;
      };
      if (options.script.empty() && !io.WantCaptureKeyboard) {
        const glm::vec3 forward(std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        glm::vec3 move(0);
        if (down(GLFW_KEY_W)) move += forward;
        if (down(GLFW_KEY_S)) move -= forward;
        if (down(GLFW_KEY_D)) move += right;
        if (down(GLFW_KEY_A)) move -= right;
        if (!io.WantCaptureMouse) {
          if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) yaw += io.MouseDelta.x * 0.004f, pitch = glm::clamp(pitch - io.MouseDelta.y * 0.004f, -1.5f, 1.5f);
          speed *= std::pow(1.25f, io.MouseWheel);  // 10 m and 50 km are both a few wheel turns away
          if (b && ImGui::IsMouseDown(ImGuiMouseButton_Left)) divider = glm::clamp(io.MousePos.x / width, 0.0f, 1.0f);
          magnifierAt = {io.MousePos.x, io.MousePos.y};
        }
        if (pressed(GLFW_KEY_P)) playing = !playing;
        if (pressed(GLFW_KEY_Z)) magnifier = !magnifier;
        if (pressed(GLFW_KEY_M)) {
          const auto at = std::find(methods.begin(), methods.end(), a.method);
          a.setMethod(methods[at == methods.end() ? 0 : (at - methods.begin() + 1) % methods.size()], options.base);
        }
        if (pressed(GLFW_KEY_F12)) screenshot = "retroaa-screenshot.png";
        // N, B, E: cycle sample count, resolve weighting, edge detector.
        if (pressed(GLFW_KEY_N)) a.config.samples = a.config.samples >= 16 ? 1 : a.config.samples * 2, a.apply();
        if (pressed(GLFW_KEY_B)) a.config.resolveWeighting = retroaa::ResolveWeighting((int(a.config.resolveWeighting) + 1) % 5), a.apply();
        if (pressed(GLFW_KEY_E)) a.config.edgeDetector = retroaa::EdgeDetector((int(a.config.edgeDetector) + 1) % 6), a.apply();
        if (pressed(GLFW_KEY_R)) {
          recording = !recording;
          if (!recording && recorded.size() >= 2) {
            nlohmann::json keys = nlohmann::json::array();
            for (const auto& k : recorded)
              keys.push_back({{"t", k.time}, {"position", {k.position.x, k.position.y, k.position.z}}, {"target", {k.target.x, k.target.y, k.target.z}}});
            std::ofstream(options.recordPath) << nlohmann::json{{"fps", 30}, {"keys", keys}}.dump(1) << "\n";
            std::printf("view: recorded %zu keys to %s\n", recorded.size(), options.recordPath.c_str());
          }
          if (recording) recorded.clear();
        }
        camera.position += move * speed * float(timeStep);
        camera.target = camera.position + forward;
        if (playing) camera = scene.path.at(scene.camera, pathFrame++ % std::max(scene.path.frameCount(), 1));
        if (recording && frame % 8 == 0) recorded.push_back({float(recorded.size() * 8 * timeStep), camera.position, camera.target});
        if (pressed(GLFW_KEY_G)) {
          const host::GroundTruth truth = host::renderGroundTruth(*a.renderer, camera, 8);
          a.renderer->renderFrame(camera);
          const ErrorMetrics m = compare(DisplayImage::fromRgba8(width, height, a.renderer->readDisplay()),
                                         DisplayImage::fromRgba8(width, height, truth.display), edgeMaskFromSpread(truth.lumaStdDev));
          char text[160];
          std::snprintf(text, sizeof text, "%s vs 8×8 ground truth: PSNR %.2f dB, edge PSNR %.2f dB", a.method.c_str(), m.psnrDb, m.edgePsnrDb);
          groundTruthText = text;
        }
      }
      // Render both sides through the host's own pipeline, then compose into the window.
      a.renderer->renderFrame(camera);
      if (b) b->renderer->renderFrame(camera);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
      glViewport(0, 0, width, height);
      const int split = b ? int(divider * width) : width;
      glBlitNamedFramebuffer(a.renderer->targets().displayFramebuffer, 0, 0, 0, split, height, 0, 0, split, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      if (b) {
        glBlitNamedFramebuffer(b->renderer->targets().displayFramebuffer, 0, split, 0, width, height, split, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glEnable(GL_SCISSOR_TEST);  // the divider: a 2-pixel white line
        glScissor(std::max(split - 1, 0), 0, 2, height);
        glClearColor(1, 1, 1, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
      }
      if (magnifier) {  // nearest-neighbour zoom of the region under the cursor, in the top-right corner
        const int lens = std::min(width, height) / 3, source = std::max(lens / magnifierZoom, 1);
        const int sx = glm::clamp(int(magnifierAt.x) - source / 2, 0, width - source);
        const int sy = glm::clamp(height - int(magnifierAt.y) - source / 2, 0, height - source);
        const GLuint from = (b && sx >= split) ? b->renderer->targets().displayFramebuffer : a.renderer->targets().displayFramebuffer;
        glBlitNamedFramebuffer(from, 0, sx, sy, sx + source, sy + source, width - lens, height - lens, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      }
      if (!screenshot.empty()) {  // the composed view, without the panel
        std::map<std::string, std::string> meta = {{"retroaa:method", a.method}, {"retroaa:scene", scene.name},
                                                    {"retroaa:config", retroaa::toConfigText(a.hooks->plugin().config())}};
        if (b) meta["retroaa:compare"] = b->method;
        const auto parent = std::filesystem::path(screenshot).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent);
        writeImage8(screenshot, width, height, readWindow(width, height), meta);
        std::printf("view: screenshot %s (%dx%d, %s)\n", screenshot.c_str(), width, height, a.method.c_str());
        if (b) {  // and each side whole, as its own method renders it
          const std::string stem = (std::filesystem::path(screenshot).parent_path() / std::filesystem::path(screenshot).stem()).string();
          writeImage8(stem + "-a.png", width, height, a.renderer->readDisplay(), {{"retroaa:method", a.method}});
          writeImage8(stem + "-b.png", width, height, b->renderer->readDisplay(), {{"retroaa:method", b->method}});
        }
      }
      // The panel: method and settings, what they cost, what they buy.
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
      ImGui::Begin("retroaa");
      int methodIndex = int(std::find(methods.begin(), methods.end(), a.method) - methods.begin());
      if (ImGui::BeginCombo("method", a.method.c_str())) {
        for (int i = 0; i < int(methods.size()); ++i)
          if (ImGui::Selectable(methods[i].c_str(), i == methodIndex)) a.setMethod(methods[i], options.base);
        ImGui::EndCombo();
      }
      bool changed = false;
      int samplesIndex = a.config.samples == 1 ? 0 : a.config.samples == 2 ? 1 : a.config.samples == 4 ? 2 : a.config.samples == 8 ? 3 : 4;
      const char* sampleNames[] = {"1", "2", "4", "8", "16"};
      if (ImGui::Combo("samples", &samplesIndex, sampleNames, 5)) a.config.samples = 1 << samplesIndex, changed = true;
      int weighting = int(a.config.resolveWeighting);
      const char* weightings[] = {"median", "front", "back", "fso", "mean"};
      if (ImGui::Combo("resolve weighting", &weighting, weightings, 5)) a.config.resolveWeighting = retroaa::ResolveWeighting(weighting), changed = true;
      int detector = int(a.config.edgeDetector);
      const char* detectors[] = {"depth", "plane", "normal", "material", "coverage", "every_pixel"};
      if (ImGui::Combo("edge detector", &detector, detectors, 6)) a.config.edgeDetector = retroaa::EdgeDetector(detector), changed = true;
      changed |= ImGui::SliderFloat("closeness c", &a.config.closeness, 0.0f, 20.0f);
      changed |= ImGui::SliderFloat("adaptive shading scale", &a.config.adaptiveShadingScale, 0.0f, 16.0f);
      changed |= ImGui::SliderInt("aggregates c", &a.config.aggregateCount, 1, 4);
      changed |= ImGui::SliderFloat("coverage tolerance", &a.config.coverageTolerance, 0.0f, 8.0f);
      changed |= ImGui::Checkbox("fxaa on top", &a.config.fxaa);
      // Every other key, by name (the config reference lists them).
      static char setting[128] = "";
      static std::string settingError;
      if (ImGui::InputText("key=value", setting, sizeof setting, ImGuiInputTextFlags_EnterReturnsTrue)) {
        const std::string text = setting;
        const size_t equals = text.find('=');
        retroaa::Config updated = a.config;
        const retroaa::Status s = equals == std::string::npos ? retroaa::Status(retroaa::Error{retroaa::ErrorCode::InvalidConfig, "expected key=value"})
                                                               : retroaa::applySetting(updated, text.substr(0, equals), text.substr(equals + 1));
        settingError = s ? "" : s.error().message;
        if (s) a.config = updated, changed = true;
      }
      if (!settingError.empty()) ImGui::TextWrapped("%s", settingError.c_str());
      if (changed) a.apply();
      const retroaa::Stats stats = a.hooks->plugin().stats();
      ImGui::Separator();
      ImGui::Text("%d×%d, %d samples, %.3f lighting evaluations/pixel", width, height, stats.samples, stats.evaluationsPerPixel());
      ImGui::Text("plugin memory %.1f MiB (%.0f B/px), %d GL objects", stats.bytesHeld / 1048576.0, double(stats.bytesHeld) / (double(width) * height), stats.glObjectsHeld);
      std::map<std::string, double> passTotals;  // a pass runs once per slice: one line each
      for (const retroaa::PassTime& pass : stats.passes) passTotals[pass.name] += pass.ms;
      for (const auto& [name, ms] : passTotals) ImGui::Text("  %s: %.2f ms", name.c_str(), ms);

      ImGui::TextWrapped("%s", groundTruthText.c_str());
      ImGui::TextWrapped("WASD + right mouse: fly; wheel: speed %.1f m/s; P: play path; R: record path%s; M: next method; N/B/E: samples/weighting/detector; Z: magnifier; G: ground truth; F12: screenshot%s",
                         speed, recording ? " (recording)" : "", b ? "; left drag: divider" : "");
      if (b) ImGui::Text("split: %s | %s", a.method.c_str(), b->method.c_str());
      ImGui::End();
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (!screenshotWithPanel.empty()) {
        writeImage8(screenshotWithPanel, width, height, readWindow(width, height), {{"retroaa:method", a.method}});
        std::printf("view: screenshot with the panel %s\n", screenshotWithPanel.c_str());
      }
      glfwSwapBuffers(window);
      if (!a.hooks->lastError().empty()) {
        std::fprintf(stderr, "view: plugin error: %s\n", a.hooks->lastError().c_str());
        status = kExitCheckFailed;
        break;
      }
    }
    a.setMethod("off", options.base);
    a.renderer->renderFrame(camera);
    const int objectsAtEnd = a.hooks->plugin().stats().glObjectsHeld;
    std::printf("view: %d GL errors; plugin GL objects %d at start, %d at the end (method off)\n", glErrors, objectsAtStart, objectsAtEnd);
    if (glErrors > 0 || objectsAtEnd != objectsAtStart) status = kExitCheckFailed;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace app
