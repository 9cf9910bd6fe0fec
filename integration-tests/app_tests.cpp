// The `retroaa` command as users meet it: exit codes, messages, written files.
#include "commands.h"
#include "image_io.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
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
  EXPECT_NE(r.output.find("'samples': unsupported value '3'"), std::string::npos) << r.output;

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

  // A multisampled G-buffer over the plugin's budget is refused before the host's own targets exist (at this size
  // they alone took 3.6 GB and 6 s before the refusal); a supersampled one by its factor.
  r = runCli("render --method edge --width 8192 --height 8192 --out " + temp("x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("edge: the MSAA G-buffer would take 8192 x 8192 x 4 samples x 40 B = 10.00 GiB, over its "
                          "budget of 8192 MiB"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("GL debug"), std::string::npos) << r.output;
  r = runCli("bench --methods off,ssaa@supersample=4 --width 4096 --height 4096 --json " + temp("bench.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("x 16 samples x 40 B"), std::string::npos) << r.output;

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
  const auto [r, document] = runBench(
      "--methods off,fxaa,resolve,per-sample --width 64 --height 48 --gt-samples 4 --repeats 1 --wall-frames 3");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(document["rows"].size(), 4u);
  EXPECT_GE(document["gl_max_samples"].get<int>(), 1);
  EXPECT_GT(document["copy_gb_per_s"].get<double>(), 0.0);
  // The shading floor: at least one surface per pixel, more on a frame with silhouettes, at most N.
  const double floor = document["shading_floor_evals_per_pixel"].get<double>();
  EXPECT_GT(floor, 1.0);
  EXPECT_LT(floor, 4.0);
  for (const auto& row : document["rows"]) {
    for (const char* field :
         {"method", "samples", "evals_per_pixel", "gpu_ms", "passes_ms", "plugin_bytes_per_pixel", "psnr_db",
          "edge_psnr_db", "psnr_vs_per_sample_db", "max_abs_error", "time_vs_off", "passes_fragment_invocations",
          "passes_compute_invocations", "passes_minimum_bytes", "passes_traffic_bound_ms"})
      EXPECT_TRUE(row.contains(field)) << field;
    for (const char* figure : {"wall_ms", "wall_vs_off", "plugin_overhead_ms", "evals_vs_shading_floor"})
      EXPECT_TRUE(row[figure].is_number()) << figure << " of " << row.dump();
    EXPECT_GT(row["wall_ms"].get<double>(), 0.0);
  }
  EXPECT_EQ(document["rows"][0]["wall_vs_off"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(document["rows"][3]["evals_vs_shading_floor"].get<double>(), 4.0 / floor);
  EXPECT_GT(document["rows"][2]["passes_minimum_bytes"]["plugin.resolve"].get<uint64_t>(), 0u);
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

// Every relative link in README.md and docs/ (Markdown links, and pages named in the text as
// docs/NAME.md, ../NAME.md or NAME.md in capitals) points at a file of the repository.
TEST(Docs, EveryRelativeLinkResolves) {
  namespace fs = std::filesystem;
  const fs::path root = RETROAA_SOURCE_DIR;
  std::vector<fs::path> pages = {root / "README.md"};
  for (const auto& entry : fs::recursive_directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  const std::regex markdownLink(R"(\]\(([^)\s]+)\))"),
      namedPage(R"((?:^|[\s(`])((?:\.\./|docs/)[\w./-]+\.md|[A-Z][A-Z_]+\.md)\b)");
  int links = 0;
  for (const fs::path& page : pages) {
    std::ifstream in(page);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    auto check = [&](const std::string& target, bool fromRoot) {
      if (target.rfind("http", 0) == 0 || target.rfind("mailto:", 0) == 0 || target[0] == '#') return;
      const std::string path = target.substr(0, target.find('#'));
      const bool resolves = fs::exists(page.parent_path() / path) || (fromRoot && fs::exists(root / path));
      EXPECT_TRUE(resolves) << page.lexically_relative(root).string() << " links to '" << target
                            << "', which does not exist";
      ++links;
    };
    for (std::sregex_iterator m(text.begin(), text.end(), markdownLink), end; m != end; ++m) check((*m)[1], false);
    for (std::sregex_iterator m(text.begin(), text.end(), namedPage), end; m != end; ++m) check((*m)[1], true);
  }
  EXPECT_GT(links, 30);
  // The config reference names pages too.
  for (const retroaa::ConfigKey& key : retroaa::configKeys()) {
    const std::string effect = key.effect;
    for (std::sregex_iterator m(effect.begin(), effect.end(), namedPage), end; m != end; ++m)
      EXPECT_TRUE(fs::exists(root / (*m)[1].str())) << "config key " << key.name << " names " << (*m)[1];
  }
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

TEST(Cli, ShowingSliceCountsOfAMethodWithoutSlicesIsRefused) {
  CliRun r = runCli("render --method resolve --show edges --width 32 --height 24 --out " + temp("edges.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(
                "--show edges needs a method that lights some pixels more than once; resolve lights every pixel once"),
            std::string::npos)
      << r.output;
  r = runCli("render --method edge --show edges --width 32 --height 24 --out " + temp("edges.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  // The count it prints is the frame's (every pixel lit at least once), not an empty query ring's 0.
  float evaluations = 0;
  const size_t line = r.output.find("edges: ");
  ASSERT_NE(line, std::string::npos) << r.output;
  ASSERT_EQ(std::sscanf(r.output.c_str() + line, "edges: %f lighting evaluations per pixel", &evaluations), 1)
      << r.output;
  EXPECT_GE(evaluations, 1.0f) << r.output;
}

// A frame whose ground truth has no edge pixel has no edge error: null in JSON, n/a in the table.
TEST(Cli, EdgeFiguresOfAFrameWithoutEdgesAreNotApplicable) {
  const std::string scene = temp("sky-only.json");
  std::ofstream(scene) << R"({"camera": {"position": [0,0,5], "target": [0,0,0]}, "materials": [{"name": "m"}],
                             "objects": [], "star_density": 0})";
  const auto [r, document] =
      runBench("--scene " + scene + " --methods off,edge --width 48 --height 32 --gt-samples 2 --repeats 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(document["edge_pixels"], 0);
  EXPECT_EQ(document["shading_floor_evals_per_pixel"].get<double>(), 1.0) << "one surface (the sky) per pixel";
  for (const auto& row : document["rows"]) {
    EXPECT_TRUE(row["edge_psnr_db"].is_null()) << row.dump();
    EXPECT_EQ(row["edge_pixels"], 0);
    EXPECT_TRUE(row["psnr_db"].is_number());
  }
  EXPECT_NE(r.output.find("| off | 1 | 1.000 |"), std::string::npos) << r.output;
  // The table's edge PSNR column reads n/a in every row, never a number.
  auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    std::string cell;
    while (std::getline(in, cell, '|')) out.push_back(cell);
    return out;
  };
  std::istringstream lines(r.output);
  std::string line;
  int column = -1, rows = 0;
  while (std::getline(lines, line)) {
    if (line.empty() && column >= 0) break;  // the table's end (the passes' floors follow)
    if (line.rfind("| method", 0) == 0) {
      const auto header = cells(line);
      for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == " edge PSNR dB ") column = int(i);
    } else if (column >= 0 && (line.rfind("| off ", 0) == 0 || line.rfind("| edge ", 0) == 0)) {
      EXPECT_EQ(cells(line).at(size_t(column)), " n/a ") << line;
      ++rows;
    }
  }
  EXPECT_EQ(rows, 2) << r.output;
}

TEST(Cli, ScoreRatesAForeignEnginesCapturesAgainstItsSupersampledReference) {
  // A 4x reference of a hard vertical edge at x = 8.5 pixels (of 16): black left, white right. The
  // capture `exact` is its box filter, `jagged` snaps the edge pixel to black, `dimmed` lowers the
  // pixels from x = 12 on by 2/255. The reference's background.png marks x >= 40 (capture x >= 10) as
  // having no geometry (the sky).
  const std::string dir = temp("score");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const int w = 16, h = 12, f = 4;  // SSIM needs 11x11
  std::vector<uint8_t> reference(size_t(w * f) * h * f * 4, 255);
  for (int y = 0; y < h * f; ++y)
    for (int x = 0; x < w * f; ++x)
      for (int c = 0; c < 3; ++c) reference[(size_t(y) * w * f + x) * 4 + c] = x < 34 ? 0 : 255;
  app::writeImage8(dir + "/reference.png", w * f, h * f, reference);
  auto capture = [&](const std::string& name, auto value) {
    std::vector<uint8_t> rgba(size_t(w) * h * 4, 255);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) rgba[(size_t(y) * w + x) * 4 + c] = value(x);
    app::writeImage8(dir + "/" + name + ".png", w, h, rgba);
  };
  // Half the edge pixel's sub-pixels are white: 0.5 in linear light is 188 in sRGB.
  capture("exact", [](int x) { return uint8_t(x < 8 ? 0 : x == 8 ? 188 : 255); });
  capture("jagged", [](int x) { return uint8_t(x <= 8 ? 0 : 255); });
  capture("dimmed", [](int x) { return uint8_t(x < 8 ? 0 : x == 8 ? 188 : x < 12 ? 255 : 253); });
  std::vector<uint8_t> background(reference.size(), 255);
  for (int y = 0; y < h * f; ++y)
    for (int x = 0; x < w * f; ++x)
      for (int c = 0; c < 3; ++c) background[(size_t(y) * w * f + x) * 4 + c] = x >= 40 ? 255 : 0;
  std::filesystem::create_directories(dir + "/ref");
  app::writeImage8(dir + "/ref/background.png", w * f, h * f, background);
  app::writeImage8(dir + "/ref/reference.png", w * f, h * f, reference);
  std::ofstream(dir + "/capture.jsonl")
      << R"({"spec": "off", "image": "jagged.png", "wall_ms": 10, "gl_errors": 0, "retroaa": {}})"
      << "\n"
      << R"({"spec": "edge", "image": "exact.png", "wall_ms": 25, "gl_errors": 0,)"
      << R"( "retroaa": {"evaluations_per_pixel": 1.25, "plugin_bytes": 1048576, "passes": {"resolve": 1.5}}})"
      << "\n"
      << R"({"spec": "fxaa", "image": "dimmed.png", "wall_ms": 12})"
      << "\n"
      << R"({"spec": "broken", "error": "not selected"})"
      << "\n";

  CliRun r = runCli("score " + dir + " --reference " + dir + "/ref/reference.png --factor 4");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("broken was not captured: not selected"), std::string::npos) << r.output;
  nlohmann::json report;
  std::ifstream(dir + "/report.json") >> report;
  ASSERT_EQ(report.size(), 3u);
  EXPECT_EQ(report[0]["spec"], "off");
  EXPECT_EQ(report[0]["edge_pixels"], h) << "one edge pixel a row";
  EXPECT_LT(report[0]["edge_psnr_db"].get<double>(), 10.0) << "the jagged edge pixel is half wrong";
  EXPECT_GT(report[1]["edge_psnr_db"].get<double>(), 45.0) << "the box filter itself";
  EXPECT_DOUBLE_EQ(report[1]["wall_vs_off"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(report[1]["evaluations_per_pixel"].get<double>(), 1.25);
  // Sky pixels: x = 11..14 (all 3x3 neighbours marked), rows 1..10. `dimmed` changes x = 12..14.
  EXPECT_EQ(report[0]["sky_pixels"], 40);
  EXPECT_DOUBLE_EQ(report[1]["sky_kept"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(report[2]["sky_kept"].get<double>(), 0.25);

  r = runCli("score " + dir + " --reference " + dir + "/reference.png --factor 2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("jagged.png is 16x12; the reference filtered by 2 is 32x24"), std::string::npos) << r.output;
  r = runCli("score " + temp("nowhere") + " --reference " + dir + "/reference.png");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("capture.jsonl: cannot read"), std::string::npos) << r.output;
}

TEST(Cli, ScoreTellsTheSkysOwnEdgesFromTheModels) {
  // A 4x reference: geometry (black) left of x = 8.5 pixels, sky right of it with a step of its own (a
  // cloud's rim) at x = 12.5, white to grey; background.png marks the sky. The capture `exact` is the
  // box filter; `cloudless` gets the geometry's edge right and draws the cloud's rim a pixel late in the sky.
  const std::string dir = temp("score-sky");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/ref");
  const int w = 16, h = 12, f = 4;
  std::vector<uint8_t> reference(size_t(w * f) * h * f * 4, 255), background(reference.size(), 255);
  for (int y = 0; y < h * f; ++y)
    for (int x = 0; x < w * f; ++x)
      for (int c = 0; c < 3; ++c) {
        reference[(size_t(y) * w * f + x) * 4 + c] = x < 34 ? 0 : x < 50 ? 255 : 128;
        background[(size_t(y) * w * f + x) * 4 + c] = x >= 34 ? 255 : 0;
      }
  app::writeImage8(dir + "/ref/reference.png", w * f, h * f, reference);
  app::writeImage8(dir + "/ref/background.png", w * f, h * f, background);
  auto capture = [&](const std::string& name, int skyRim) {  // the rim's column in the sky's rows
    std::vector<uint8_t> rgba(size_t(w) * h * 4, 255);
    for (int y = 0; y < h; ++y) {
      const int rim = y == 0 || y == h - 1 ? 12 : skyRim;  // rows 0 and h-1 are not sky: always right
      for (int x = 0; x < w; ++x)  // the means in linear light: of 0 and 255, 188; of 255 and 128, 205
        for (int c = 0; c < 3; ++c)
          rgba[(size_t(y) * w + x) * 4 + c] = x < 8 ? 0 : x == 8 ? 188 : x < rim ? 255 : x == rim ? 205 : 128;
    }
    app::writeImage8(dir + "/" + name + ".png", w, h, rgba);
  };
  capture("exact", 12);
  capture("cloudless", 13);
  std::ofstream(dir + "/capture.jsonl") << R"({"spec": "off", "image": "exact.png"})"
                                        << "\n"
                                        << R"({"spec": "late-rim", "image": "cloudless.png"})"
                                        << "\n";
  CliRun r = runCli("score " + dir + " --reference " + dir + "/ref/reference.png --factor 4");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json report;
  std::ifstream(dir + "/report.json") >> report;
  ASSERT_EQ(report.size(), 2u);
  // Sky: x = 10..14 (every 3x3 neighbour marked), rows 1..10; the rim's pixel x = 12 is an edge in it.
  EXPECT_EQ(report[0]["edge_pixels"], 2 * h);
  EXPECT_EQ(report[0]["background_edge_pixels"], h - 2);
  EXPECT_EQ(report[0]["model_edge_pixels"], h + 2) << "the rim's top and bottom rows are not sky";
  EXPECT_GT(report[1]["model_edge_psnr_db"].get<double>(), 30.0) << "the geometry's edge is right";
  EXPECT_LT(report[1]["background_edge_psnr_db"].get<double>(), 25.0) << "the rim is a pixel late";
  EXPECT_LT(report[1]["edge_psnr_db"].get<double>(), report[1]["model_edge_psnr_db"].get<double>());
  EXPECT_NE(r.output.find("model edge dB"), std::string::npos) << r.output;
}
