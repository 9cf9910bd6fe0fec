// `retroaa view` under Xvfb (a real window through Mesa's GLX): scripted runs, screenshots against the
// headless renders of the same camera and settings, and a resize storm.
#include "commands.h"
#include "image_io.h"
#include "measure.h"
#include "test_support.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace testing_support;
namespace fs = std::filesystem;

namespace {
CliRun view(const fs::path& script, int width, int height) {
  // The viewer's own exit code is echoed from inside: xvfb-run sometimes fails to clean up its
  // temporary folder after a quick run and then replaces the command's exit code with its own.
  CliRun run = runCommand("xvfb-run -a -s '-screen 0 1280x1024x24' sh -c '" + std::string(RETROAA_CLI) +
                          " view --width " + std::to_string(width) + " --height " + std::to_string(height) +
                          " --script " + script.string() + "; echo retroaa-exit=$?'");
  const size_t at = run.output.rfind("retroaa-exit=");
  run.exitCode = at == std::string::npos ? -1 : std::stoi(run.output.substr(at + 13));
  return run;
}

// The run ended with `exitCode` and its output says `fragment`.
void expectRun(const CliRun& run, int exitCode, const std::string& fragment) {
  EXPECT_EQ(run.exitCode, exitCode) << run.output;
  EXPECT_NE(run.output.find(fragment), std::string::npos) << run.output;
}

// Writes `text` as a script in a folder of the test's own and runs the viewer on it.
CliRun viewScript(const std::string& name, const std::string& text, int width, int height) {
  const fs::path dir = fs::temp_directory_path() / ("retroaa_viewer_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / (name + ".txt")) << text;
  return view(dir / (name + ".txt"), width, height);
}
}  // namespace

TEST(Viewer, ScreenshotsOfEveryMethodAtThreeSizesMatchTheHeadlessRenders) {
  const fs::path dir = fs::temp_directory_path() / "retroaa_viewer";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::string> methods = app::expandMethodList("all");
  const int sizes[3][2] = {{160, 120}, {200, 150}, {128, 96}};
  std::ofstream script(dir / "script.txt");
  int frame = 0;
  for (int s = 0; s < 3; ++s) {
    script << frame << " resize " << sizes[s][0] << " " << sizes[s][1] << "\n";
    frame += 2;  // the window system applies the size on a later frame
    for (const std::string& m : methods) {
      script << frame << " method " << m << "\n"
             << frame + 1 << " screenshot " << (dir / (std::to_string(s) + "-" + m + ".png")).string() << "\n";
      frame += 2;
    }
  }
  script << frame << " quit\n";
  script.close();
  const CliRun run = view(dir / "script.txt", sizes[0][0], sizes[0][1]);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("view: 0 GL errors"), std::string::npos) << run.output;
  for (int s = 0; s < 3; ++s) {
    PatchedHost host("default", sizes[s][0], sizes[s][1]);
    for (const std::string& m : methods) {
      int w = 0, h = 0;
      const fs::path shot = dir / (std::to_string(s) + "-" + m + ".png");
      ASSERT_TRUE(fs::exists(shot)) << shot << "\n" << run.output;
      app::DisplayImage windowed;
      windowed.rgb = app::readImageRgb(shot.string(), w, h);
      windowed.width = w, windowed.height = h;
      ASSERT_EQ(w, sizes[s][0]) << m;
      ASSERT_EQ(h, sizes[s][1]) << m;
      app::DisplayImage headless = host.render(m);
      // A history (temporal): the screenshot is the second frame after the switch.
      if (retroaa::historyFrames(app::parseMethodSpec(m, {}).config) > 0) {
        host.renderer->renderFrame(host.scene.camera);
        headless = app::DisplayImage::fromRgba8(w, h, host.renderer->readDisplay());
      }
      const double psnr = app::compare(windowed, headless, {}).psnrDb;
      EXPECT_GE(psnr, 50.0) << m << " at " << w << "x" << h;  // the project's image tolerance: same pipeline
    }
  }
}

TEST(Viewer, ResizeStormLeavesNoObjectAndNoGlError) {
  std::ostringstream script;
  const char* methods[] = {"edge", "resolve+coverage", "aggregate",  "adaptive",
                           "fxaa", "coverage",         "per-sample", "off"};
  for (int i = 0; i < 200; ++i) {
    script << i << " resize " << 64 + (i * 37) % 97 << " " << 48 + (i * 53) % 71 << "\n";
    if (i % 3 == 0) script << i << " method " << methods[(i / 3) % 8] << "\n";
  }
  script << 201 << " quit\n";
  expectRun(viewScript("storm", script.str(), 96, 72), 0,
            "view: 0 GL errors; plugin GL objects 2 at start, 2 at the end");
}

TEST(Viewer, ABadScriptLineIsNamed) {
  expectRun(viewScript("bad", "0 method edge\n1 teleport 1 2 3\n", 64, 48), 2, "bad.txt:2: unknown action 'teleport'");
}

TEST(Viewer, AScriptThatIsNotARegularFileIsRefused) {
  // /dev/zero would otherwise be read forever.
  expectRun(view("/dev/zero", 64, 48), 2, "/dev/zero: cannot open script: it is not a regular file");
}

TEST(Viewer, ReportsItsFrameTime) {
  expectRun(viewScript("time", "0 method edge\n5 quit\n", 64, 48), 0, "frames timed, median frame");
}
