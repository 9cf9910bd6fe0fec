// `retroaa regress` and `retroaa record`: deterministic playback, goldens that catch a degraded
// method, and a report whose every reference exists.
#include "test_support.h"

#include "commands.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <sstream>

using namespace testing_support;
namespace fs = std::filesystem;

namespace {
fs::path tempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("retroaa_regress_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
const char* kSmallRun = "default --frames 2 --width 96 --height 72 --gt-samples 3";
}  // namespace

TEST(Regress, CommittedGoldensHoldForEveryMethodRegressRuns) {
  // regress's own method list: a method that joins it without committed figures fails here.
  const fs::path out = tempDir("subset");
  const CliRun run = runCli(std::string("regress ") + kSmallRun + " --out " + out.string() + " --golden-dir " +
                            RETROAA_SOURCE_DIR + "/integration-tests/golden/ci --check");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("check: every figure within tolerance"), std::string::npos) << run.output;
}

TEST(Regress, CheckFailsNamingTheFigureWhenAMethodIsDegraded) {
  const fs::path out = tempDir("degraded"), golden = tempDir("degraded_golden");
  const std::string common = std::string("regress ") + kSmallRun + " --methods off,resolve --out " + out.string() +
                             " --golden-dir " + golden.string();
  ASSERT_EQ(runCli(common + " --update-golden").exitCode, 0);
  EXPECT_EQ(runCli(common + " --check").exitCode, 0);
  // A resolve with c = 0 keeps only its reference sample: no intra-model smoothing.
  const CliRun degraded = runCli(common + " --check --set closeness=0");
  EXPECT_EQ(degraded.exitCode, 1) << degraded.output;
  EXPECT_NE(degraded.output.find("WORSE: default / resolve: edge_psnr_db fell from"), std::string::npos)
      << degraded.output;
  EXPECT_EQ(degraded.output.find("default / off:"), std::string::npos) << "off did not change: " << degraded.output;
  // A method the goldens do not hold yet is new, not worse, and fails the check until its figures are added;
  // adding them keeps the others'.
  const std::string withFxaa = std::string("regress ") + kSmallRun + " --methods off,resolve,fxaa --out " +
                               out.string() + " --golden-dir " + golden.string();
  const CliRun fresh = runCli(withFxaa + " --check");
  EXPECT_EQ(fresh.exitCode, 1) << fresh.output;
  EXPECT_NE(fresh.output.find("NEW: default / fxaa: no golden figures yet"), std::string::npos) << fresh.output;
  EXPECT_EQ(fresh.output.find("WORSE:"), std::string::npos) << fresh.output;
  EXPECT_NE(fresh.output.find("check: 0 figures got worse, 1 methods have no golden figures yet"), std::string::npos)
      << fresh.output;
  ASSERT_EQ(runCli(std::string("regress ") + kSmallRun + " --methods fxaa --out " + out.string() + " --golden-dir " +
                   golden.string() + " --update-golden")
                .exitCode,
            0);
  EXPECT_EQ(runCli(withFxaa + " --check").exitCode, 0);
  // Goldens made with other settings are refused, not silently compared.
  const CliRun otherSize = runCli(
      std::string("regress default --frames 2 --width 64 --height 48 --gt-samples 3 --methods off,resolve --out ") +
      out.string() + " --golden-dir " + golden.string() + " --check");
  EXPECT_EQ(otherSize.exitCode, 2);
  EXPECT_NE(otherSize.output.find("golden was made with settings"), std::string::npos) << otherSize.output;
}

// An object that moves on its own (the scene's "velocity"): the lag figure is the error on the pixels
// whose ground truth changed since the previous frame. A history that follows the camera alone looks for
// the crate where it was, finds another surface there and starts again from this frame, far behind off;
// with the host's velocity attachment it follows the crate and keeps its history, and so it does with a box
// around the crate now and a frame ago (FrameInfo::movingObjects: an engine without a velocity output). (The
// gap was 5.6 dB while a restarted pixel showed the frame as sampled, off its centre by the jitter; shown at
// its centre, 1.0.) A scene where nothing moves on its own has no such figure.
TEST(Regress, AMovingObjectGivesALagFigureThatVelocityOrABoxCloses) {
  const fs::path out = tempDir("lag");
  const std::string scene = std::string(RETROAA_SOURCE_DIR) + "/integration-tests/scenes/moving_object.json";
  std::ifstream sceneFile(scene);
  const nlohmann::json document = nlohmann::json::parse(sceneFile);
  std::string scenes = scene;
  for (const char* motion : {"camera", "boxes"}) {
    nlohmann::json variant = document;
    variant["object_motion"] = motion;
    const fs::path file = out / ("moving_object_" + std::string(motion) + ".json");  // its stem names it
    std::ofstream(file) << variant.dump();
    scenes += " " + file.string();
  }
  const CliRun run =
      runCli("regress " + scenes + " default --frames 2 --stride 6 --width 96 --height 72 --gt-samples 3" +
             " --wall-frames 0 --methods off,temporal --out " + (out / "report").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(out / "report" / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  std::map<std::string, nlohmann::json> lag;
  for (const auto& s : report["scenes"])
    for (const auto& row : s["rows"])
      lag[s["scene"].get<std::string>() + "/" + row["method"].get<std::string>()] = row["lag_psnr_db"];
  for (const char* key :
       {"moving_object/off", "moving_object/temporal", "moving_object_camera/temporal", "moving_object_boxes/temporal"})
    ASSERT_TRUE(lag[key].is_number()) << key << ": " << lag[key];
  const double off = lag["moving_object/off"], followed = lag["moving_object/temporal"],
               cameraOnly = lag["moving_object_camera/temporal"], boxes = lag["moving_object_boxes/temporal"];
  std::printf(
      "lag PSNR: off %.2f dB, temporal %.2f dB with the velocity attachment, %.2f dB with boxes, %.2f dB "
      "with the camera alone\n",
      off, followed, boxes, cameraOnly);
  EXPECT_LT(cameraOnly, off - 3.0);
  EXPECT_GT(followed, cameraOnly + 0.5);
  EXPECT_NEAR(boxes, followed, 0.05);
  EXPECT_TRUE(lag["default/off"].is_null()) << lag["default/off"];
}

// The same camera path played at four times its frame rate, measured at the same moments: `temporal`
// has four times the frames to average and moves a quarter as far between them, so it must not come out
// blurrier. A history whose blend and clip followed the distance moved rather than the motion itself was:
// slower frames kept it longer, and each frame resampled it again (0.3 dB under here, up to 3.0 dB on
// the recorded paths at 160x120; docs/methods/temporal.md).
TEST(Regress, TemporalAtFourTimesTheFrameRateIsNoBlurrier) {
  const fs::path out = tempDir("frame_rate");
  const fs::path scenes = fs::path(RETROAA_SOURCE_DIR) / "integration-tests" / "scenes";
  std::ifstream sceneFile(scenes / "engine.json"), pathFile(scenes / "paths" / "engine.json");
  nlohmann::json fast = nlohmann::json::parse(sceneFile), path = nlohmann::json::parse(pathFile);
  path["fps"] = 4 * path["fps"].get<double>();
  fast["camera_path"] = path;
  std::ofstream(out / "engine_fast.json") << fast.dump();
  const auto interior = [&](const std::string& scene, int stride) {
    const fs::path report = out / ("report" + std::to_string(stride));
    const CliRun run =
        runCli("regress " + scene + " --frames 4 --stride " + std::to_string(stride) +
               " --width 128 --height 96 --gt-samples 3 --wall-frames 0 --methods temporal --out " + report.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(report / "report.json");
    return nlohmann::json::parse(in)["scenes"][0]["rows"][0]["interior_psnr_db"].get<double>();
  };
  const double recorded = interior((scenes / "engine.json").string(), 7);
  const double fourTimes = interior((out / "engine_fast.json").string(), 28);
  std::printf("temporal interior PSNR: %.2f dB at the path's frame rate, %.2f dB at 4x\n", recorded, fourTimes);
  EXPECT_GT(fourTimes, recorded - 0.25);
}

TEST(Regress, ReportHtmlIsWellFormedAndEveryReferenceExists) {
  const fs::path out = tempDir("report");
  ASSERT_EQ(
      runCli(std::string("regress ") + kSmallRun + " --methods off,edge,aggregate,per-sample --out " + out.string())
          .exitCode,
      0);
  std::ifstream in(out / "report.html");
  std::stringstream text;
  text << in.rdbuf();
  const std::string html = text.str();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* tag : {"html", "body", "table", "svg", "figure", "h2"}) {
    const std::regex open(std::string("<") + tag + "[ >]"), close(std::string("</") + tag + ">");
    const auto count = [&](const std::regex& r) {
      return std::distance(std::sregex_iterator(html.begin(), html.end(), r), std::sregex_iterator());
    };
    EXPECT_EQ(count(open), count(close)) << "unbalanced <" << tag << ">";
    EXPECT_GT(count(open), 0) << tag;
  }
  const std::regex source("src=\"([^\"]+)\"");
  int images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), source); it != std::sregex_iterator(); ++it, ++images)
    EXPECT_TRUE(fs::exists(out / (*it)[1].str())) << "missing " << (*it)[1].str();
  EXPECT_GE(images, 4 * 3 + 2);  // crop, image and heat map per method, plus the ground truth's
  EXPECT_NE(html.find("<polyline"), std::string::npos) << "the Pareto front is drawn";
  EXPECT_NE(html.find("Pareto front: no cheaper point is better"), std::string::npos) << "with a legend";
  for (const char* method : {"off", "edge", "aggregate", "per-sample"})  // every point carries its label
    EXPECT_TRUE(html.find(std::string("class=\"label\">") + method + "</text>") != std::string::npos ||
                html.find(std::string("class=\"label hi\">") + method + "</text>") != std::string::npos)
        << method;
  EXPECT_NE(html.find("class=\"ramp heat\""), std::string::npos) << "the heat maps' colour key";
  EXPECT_NE(html.find("class=\"ramp count\""), std::string::npos) << "the samples maps' colour key";
  EXPECT_NE(html.find("per-sample: image, error, samples per pixel (1 … 4); every pixel lit 4 times, so one colour"),
            std::string::npos)
      << "the per-sample map says why it is one colour";
  std::ifstream json(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(json);
  ASSERT_EQ(report["scenes"].size(), 1u);
  for (const auto& row : report["scenes"][0]["rows"])
    for (const char* field : {"evals_per_pixel", "gpu_ms", "passes_ms", "plugin_bytes_per_pixel", "psnr_db",
                              "edge_psnr_db", "psnr_vs_per_sample_db", "max_abs_error", "flicker"})
      EXPECT_TRUE(row.contains(field)) << field;
}

TEST(Playback, IsDeterministic) {
  // Two hosts play frame 17 of the demo path: the images are identical bit for bit.
  std::vector<std::vector<uint8_t>> images;
  for (int run = 0; run < 2; ++run) {
    PatchedHost host("default", 128, 96);
    host.hooks->plugin().reconfigure(app::parseMethodSpec("edge", {}).config);
    host.renderer->renderFrame(host.scene.path.at(host.scene.camera, 17));
    images.push_back(host.renderer->readDisplay());
  }
  EXPECT_EQ(std::hash<std::string>{}(std::string(images[0].begin(), images[0].end())),
            std::hash<std::string>{}(std::string(images[1].begin(), images[1].end())));
  EXPECT_EQ(images[0], images[1]);
}

TEST(Record, WritesAPathAScenePlaysBack) {
  const fs::path dir = tempDir("record");
  std::ofstream(dir / "scene.json") << R"({"camera": {"position": [0, 1, 10], "target": [0, 0, 0]},
    "materials": [{"name": "m"}], "objects": [{"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m"}],
    "camera_path": "orbit.json"})";
  EXPECT_THROW(host::loadScene((dir / "scene.json").string()), host::SceneError);  // not recorded yet
  const CliRun run = runCli("record --scene " + (dir / "scene.json").string() +
                            " --orbit-degrees 90 --seconds 1.5 --keys 4 --out " + (dir / "orbit.json").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const host::Scene scene = host::loadScene((dir / "scene.json").string());
  EXPECT_EQ(scene.path.frameCount(), 46);
  const host::Camera last = scene.path.at(scene.camera, 45);
  EXPECT_NEAR(glm::length(last.position - last.target), glm::length(scene.camera.position - scene.camera.target),
              1e-3f);
  EXPECT_NEAR(last.position.x, 10.0f, 0.05f);  // a quarter turn about +y (right-handed) from (0, 1, 10)
}

TEST(Regress, TheDefaultGoldensAreFoundFromAnyWorkingFolder) {
  const fs::path out = tempDir("elsewhere");
  // A run whose settings differ from the committed golden's: the golden is found and compared.
  const CliRun run = runCommand("cd " + fs::temp_directory_path().string() + " && " + RETROAA_CLI + " regress " +
                                kSmallRun + " --methods off --out " + out.string() + " --check");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(std::string(RETROAA_SOURCE_DIR) +
                            "/integration-tests/golden/default.json: golden was made with settings"),
            std::string::npos)
      << run.output;
}

TEST(Regress, ProgressCountsTheReferencesToo) {
  // 2 frames × (1 method + the frame's ground truth and per-sample reference) = 4 steps, the first a reference.
  const CliRun run =
      runCli(std::string("regress ") + kSmallRun + " --methods off --out " + tempDir("progress").string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("regress: 1/4 steps"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("ground truth and per-sample, frame 0"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("regress: 4/4 steps"), std::string::npos) << run.output;
}
