// The `retroaa` command as users meet it: exit codes, messages, written files.
#include "commands.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace testing_support;

namespace {
std::string temp(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "retroaa_app_tests";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}
}  // namespace

TEST(Cli, BadInputExitsWithCodeTwoAndNamesTheProblem) {
  CliRun r = runCli("render --method taa --out " + temp("x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("unknown value 'taa'"), std::string::npos) << r.output;

  r = runCli("render --set samples=3 --method resolve --out " + temp("x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("unsupported sample count '3'"), std::string::npos) << r.output;

  const std::string scene = temp("broken.json");
  std::ofstream(scene)
      << R"({"camera": {"position": [0,0,5], "target": [0,0,0]}, "materials": [{"name": "m", "gloss": 2}], "objects": []})";
  r = runCli("render --scene " + scene + " --out " + temp("x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("broken.json: $.materials[0].gloss: expected a finite number in [0, 1], got 2"),
            std::string::npos)
      << r.output;

  r = runCli("render --out " + temp("x.jpg2"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("--out must end in .png or .exr"), std::string::npos) << r.output;

  const std::string config = temp("bad.cfg");
  std::ofstream(config) << "method=resolve\nclosenes=3\n";
  r = runCli("render --config " + config + " --out " + temp("x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("bad.cfg:2: unknown config key 'closenes'"), std::string::npos) << r.output;

  r = runCli("render -m 6 --out " + temp("x.png"));  // FSO: warn and use 0
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("-msaa 6 is not one of 0, 4, 8, 16"), std::string::npos) << r.output;
}

TEST(Cli, RenderWritesPngWithMetadataAndExr) {
  const std::string png = temp("render.png"), exr = temp("render.exr");
  CliRun r = runCli("render --method resolve+fxaa --width 64 --height 48 --out " + png);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("GL_MAX_SAMPLES"), std::string::npos);
  r = runCli("render --method off --width 64 --height 48 --out " + exr);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  EXPECT_GT(std::filesystem::file_size(exr), 1000u);
  std::ifstream in(png, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_NE(bytes.str().find("retroaa:renderer"), std::string::npos);  // PNG text chunk
  EXPECT_NE(bytes.str().find("resolve+fxaa"), std::string::npos);
}

TEST(Cli, BenchWritesEveryRowWithTheFieldsReportsNeed) {
  const std::string json = temp("bench.json");
  const CliRun r =
      runCli("bench --methods off,fxaa,resolve --width 64 --height 48 --gt-samples 4 --repeats 1 --json " + json);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(json);
  const nlohmann::json document = nlohmann::json::parse(in);
  ASSERT_EQ(document["rows"].size(), 3u);
  EXPECT_GE(document["gl_max_samples"].get<int>(), 1);
  for (const auto& row : document["rows"])
    for (const char* field : {"method", "samples", "evals_per_pixel", "gpu_ms", "passes_ms", "plugin_bytes_per_pixel",
                              "psnr_db", "edge_psnr_db", "psnr_vs_per_sample_db", "max_abs_error", "time_vs_off"})
      EXPECT_TRUE(row.contains(field)) << field;
  EXPECT_EQ(document["rows"][0]["plugin_bytes_per_pixel"].get<double>(), 0.0);
  EXPECT_GT(document["rows"][2]["plugin_bytes_per_pixel"].get<double>(), 100.0);
  EXPECT_GT(document["rows"][2]["passes_ms"].count("plugin.resolve"), 0u);
}

TEST(Docs, ConfigReferenceMatchesTheParser) {
  std::ifstream in(std::string(RETROAA_SOURCE_DIR) + "/docs/config.md");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(app::configReference(true)), std::string::npos)
      << "docs/config.md is stale: regenerate its table with `make docs-config`";
}

// Files a user can point us at that are not regular files are refused at once (no hang on /dev/zero,
// no silent empty read of a directory), naming the file.
TEST(Cli, ScenesConfigsAndCameraPathsMustBeRegularFiles) {
  const std::string directory = temp("a-directory.cfg");
  std::filesystem::create_directories(directory);
  const std::string out = " --width 32 --height 24 --out " + temp("x.png");
  struct Case {
    std::string arguments, expected;
  };
  const std::string pathScene = temp("path-is-a-directory.json");
  std::ofstream(pathScene)
      << R"({"camera": {"position": [0,0,5], "target": [0,0,0]}, "materials": [{"name": "m"}], "objects": [], "camera_path": ")"
      << directory << R"("})";
  const Case cases[] = {
      {"render --scene /dev/zero", "/dev/zero: (file): cannot open scene file: it is not a regular file"},
      {"render --scene " + directory, directory + ": (file): cannot open scene file: it is a directory"},
      {"render --config " + directory, directory + ": cannot open config file: it is a directory"},
      {"render --config /dev/zero", "/dev/zero: cannot open config file: it is not a regular file"},
      {"render --scene " + pathScene,
       "$.camera_path: cannot open camera path file '" + directory + "': it is a directory"},
  };
  for (const Case& c : cases) {
    const CliRun r = runCli(c.arguments + out);
    EXPECT_EQ(r.exitCode, 2) << c.arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.arguments << "\n" << r.output;
  }
}
