// `retroaa`: the subcommands of commands.h, regress.h, tune.h and viewer.h. Exit codes: 0 ok, 1 a check
// failed, 2 bad usage or input (with a message naming what was wrong).
#include "commands.h"
#include "regress.h"
#include "score.h"
#include "tune.h"
#ifdef RETROAA_HAS_VIEWER
#include "viewer.h"
#endif
#include "headless_context.h"
#include "scene.h"
#include "session.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <sstream>

namespace {

// --config FILE, --set key=value, -msaa N, -post_process_aa, -aa_preset N and RETROAA_SETTINGS, in that order of
// precedence from lowest: environment, file, FSO flags, --set.
retroaa::Config buildConfig(const std::string& configFile, const std::vector<std::string>& sets,
                            const std::string& msaa, const std::string& aaPreset, bool postProcessAa) {
  retroaa::Config config;
  auto check = [](const retroaa::Status& status) {
    if (!status) throw std::invalid_argument(status.error().message);
  };
  if (const char* env = std::getenv("RETROAA_SETTINGS"))
    check(retroaa::applySettingsList(config, env, "RETROAA_SETTINGS"));
  if (!configFile.empty()) check(retroaa::applyConfigFile(config, configFile));
  std::vector<std::string> warnings;
  if (!msaa.empty()) check(retroaa::applyFsoFlag(config, "-msaa", msaa, warnings));
  if (postProcessAa) check(retroaa::applyFsoFlag(config, "-post_process_aa", "", warnings));
  if (!aaPreset.empty()) check(retroaa::applyFsoFlag(config, "-aa_preset", aaPreset, warnings));
  for (const std::string& w : warnings) std::fprintf(stderr, "retroaa: warning: %s\n", w.c_str());
  for (const std::string& set : sets) {
    const size_t equals = set.find('=');
    if (equals == std::string::npos) throw std::invalid_argument("--set expects key=value, got '" + set + "'");
    check(retroaa::applySetting(config, set.substr(0, equals), set.substr(equals + 1)));
  }
  return config;
}

// The command line: every subcommand with its options and what it runs. The config options (--config,
// --set, FSO flags) are shared; the config they build is handed to the subcommand that ran.
struct CommandLine {
  CLI::App cli{"retroaa: retrofit anti-aliasing for deferred renderers"};
  std::string configFile, msaa, aaPreset, samples;
  bool postProcessAa = false;
  std::vector<std::string> sets;
  std::vector<std::pair<CLI::App*, std::function<int(const retroaa::Config&)>>> commands;

  void addSizeOptions(CLI::App* sub, int& width, int& height) {
    sub->add_option("--width", width)->check(CLI::Range(16, 8192));
    sub->add_option("--height", height)->check(CLI::Range(16, 8192));
  }
  void addConfigOptions(CLI::App* sub) {
    sub->add_option("--config", configFile, "config file of key=value lines");
    sub->add_option("--set", sets, "one setting, key=value (repeatable)");
    sub->add_option("--samples", samples, "MSAA samples (same as --set samples=N)");
    sub->add_option("-m,--msaa", msaa, "FreeSpace Open's -msaa 0|4|8|16");
    sub->add_option("--aa_preset", aaPreset, "FreeSpace Open's -aa_preset 0..6");
    sub->add_flag("--post_process_aa", postProcessAa,
                  "FreeSpace Open's -post_process_aa (SMAA low unless --aa_preset)");
  }
  // The config options, and a command that runs with the config they build as its options' base.
  template <typename Options>
  void addConfiguredCommand(CLI::App* sub, std::shared_ptr<Options> options, int (*run)(const Options&)) {
    addConfigOptions(sub);
    commands.push_back({sub, [options, run](const retroaa::Config& config) {
                          options->base = config;
                          return run(*options);
                        }});
  }
  retroaa::Config config() {
    if (!samples.empty()) sets.insert(sets.begin(), "samples=" + samples);
    return buildConfig(configFile, sets, msaa, aaPreset, postProcessAa);
  }
};

const char* kMethodsHelp = "comma-separated method specs; 'all' (every method and variant), 'each' (one per method)";

void addHostOption(CLI::App* sub, std::string& host) {
  sub->add_option("--host", host, "host engine: fso (FreeSpace Open-shaped) or second (docs/integration.md)")
      ->check(CLI::IsMember(app::hostNames()));
}
void addGroundTruthOption(CLI::App* sub, int& samplesPerAxis) {
  sub->add_option("--gt-samples", samplesPerAxis, "ground truth supersamples per axis")->check(CLI::Range(1, 32));
}
// --methods, --width, --height and --gt-samples of a command that measures methods against ground truth.
template <typename Options>
void addMeasureOptions(CommandLine& line, CLI::App* sub, Options& options) {
  sub->add_option("--methods", options.methods, kMethodsHelp);
  line.addSizeOptions(sub, options.width, options.height);
  addGroundTruthOption(sub, options.groundTruthSamples);
}
void addWallFramesOption(CLI::App* sub, int& frames, const std::string& whichFrames) {
  sub->add_option("--wall-frames", frames,
                  "back-to-back frames per method (" + whichFrames + "), statistics off, for wall_ms (0: skip)")
      ->check(CLI::Range(0, 10000));
}

void addRender(CommandLine& line) {
  auto options = std::make_shared<app::RenderOptions>();
  CLI::App* sub = line.cli.add_subcommand("render", "render one frame headless");
  addHostOption(sub, options->host);
  sub->add_option("--scene", options->scene, "scene file, or 'default'");
  sub->add_option("--method", options->method,
                  "method[/weighting][+stacked][@key=value], or ground-truth (default: the config's)");
  line.addSizeOptions(sub, options->width, options->height);
  sub->add_option("--frame", options->frame, "camera path frame (default: the scene camera)");
  addGroundTruthOption(sub, options->groundTruthSamples);
  sub->add_option("--out", options->out, "output image (.png display, .exr linear radiance)")->required();
  sub->add_option("--heatmap", options->heatmap, "also write the error against ground truth as a heat map");
  sub->add_option("--show", options->show,
                  "write a visualisation instead: edges | samples | aggregates (lighting evaluations per pixel)");
  line.addConfiguredCommand(sub, options, app::runRender);
}

void addBench(CommandLine& line) {
  auto options = std::make_shared<app::BenchOptions>();
  CLI::App* sub = line.cli.add_subcommand("bench", "every method on one frame: speed against error");
  addHostOption(sub, options->host);
  sub->add_option("--scene", options->scene, "scene file, or 'default'");
  addMeasureOptions(line, sub, *options);
  sub->add_option("--frame", options->frame, "camera path frame (default: the scene camera)");
  sub->add_option("--repeats", options->repeats, "timed frames per method (median)")->check(CLI::Range(1, 100));
  sub->add_option("--floor-frames", options->floorFrames,
                  "frames per method timing each plugin pass's floor, apart from the timed ones (median; -1: as "
                  "--repeats, 0: skip)")
      ->check(CLI::Range(-1, 100));
  addWallFramesOption(sub, options->wallFrames, "the one frame");
  sub->add_option("--json", options->json, "write the rows as JSON");
  sub->add_option("--csv", options->csv, "write the rows as CSV");
  sub->add_option("--report", options->report, "write a Markdown report");
  sub->add_option("--images", options->imagesDirectory, "write each method's image and error heat map here");
  line.addConfiguredCommand(sub, options, app::runBench);
}

void addRecord(CommandLine& line) {
  auto options = std::make_shared<app::RecordOptions>();
  CLI::App* sub = line.cli.add_subcommand("record", "record a camera path for a scene (an orbit and dolly; no window)");
  sub->add_option("--scene", options->scene, "scene file, or 'default'");
  sub->add_option("--orbit-degrees", options->orbitDegrees, "orbit about the camera target")
      ->check(CLI::Range(-720.0, 720.0));
  sub->add_option("--dolly", options->dolly, "final distance as a multiple of the first")
      ->check(CLI::Range(0.01, 100.0));
  sub->add_option("--seconds", options->seconds, "length")->check(CLI::Range(0.01, 3600.0));
  sub->add_option("--fps", options->framesPerSecond, "playback frame rate")->check(CLI::Range(1.0, 1000.0));
  sub->add_option("--keys", options->keys, "keys along the path")->check(CLI::Range(2, 1000));
  sub->add_flag("--fit", options->fit,
                "start from a camera that frames the models' bounds (the scene camera's direction)");
  sub->add_option("--out", options->out, "camera path file (JSON)")->required();
  line.commands.push_back({sub, [options](const retroaa::Config&) { return app::runRecord(*options); }});
}

void addRegress(CommandLine& line) {
  auto options = std::make_shared<app::RegressOptions>();
  CLI::App* sub =
      line.cli.add_subcommand("regress", "every frame of recorded demo scenes with every method: report and goldens");
  addHostOption(sub, options->host);
  sub->add_option("scenes", options->scenes, "scene files (default: the five recorded scenes)");
  addMeasureOptions(line, sub, *options);
  sub->add_option("--stride", options->frameStride, "every n-th frame of each path")->check(CLI::Range(1, 1000));
  sub->add_option("--frames", options->maxFrames, "at most this many frames per scene (0: all)")
      ->check(CLI::Range(0, 100000));
  addWallFramesOption(sub, options->wallFrames, "each scene's first frame");
  sub->add_option("--out", options->out, "report folder");
  sub->add_option("--golden-dir", options->goldenDirectory,
                  "where the goldens live (default: the source tree's integration-tests/golden)");
  sub->add_flag("--check", options->check,
                "compare with the goldens; exit 1 naming each figure that got worse and each method they lack (new)");
  sub->add_flag(
      "--update-golden", options->updateGolden,
      "write this run's figures into the goldens (the methods run; the others' kept where the settings match)");
  line.addConfiguredCommand(sub, options, app::runRegress);
}

void addSoak(CommandLine& line) {
  auto options = std::make_shared<app::SoakOptions>();
  CLI::App* sub = line.cli.add_subcommand("soak", "many frames switching every setting: leaks, GL errors, memory");
  sub->add_option("--frames", options->frames)->check(CLI::Range(1, 10000000));
  line.addSizeOptions(sub, options->width, options->height);
  sub->add_option("--max-growth-mib", options->maxGrowthMiB, "allowed resident memory growth after warm-up");
  line.commands.push_back({sub, [options](const retroaa::Config&) { return app::runSoak(*options); }});
}

void addView(CommandLine& line) {
#ifdef RETROAA_HAS_VIEWER
  auto options = std::make_shared<app::ViewOptions>();
  CLI::App* sub = line.cli.add_subcommand("view", "the interactive viewer (GLFW window, Dear ImGui panel)");
  sub->add_option("--scene", options->scene, "scene file, or 'default'");
  sub->add_option("--method", options->method, "method A (left side)");
  sub->add_option("--compare", options->compare, "method B: split screen with a draggable divider");
  line.addSizeOptions(sub, options->width, options->height);
  sub->add_option("--script", options->script, "timed actions with a fixed time step (docs/viewer.md)");
  sub->add_option("--record-path", options->recordPath, "where R writes the recorded camera path");
  line.addConfiguredCommand(sub, options, app::runView);
#else
  (void)line;
#endif
}

void addTune(CommandLine& line) {
  auto options = std::make_shared<app::TuneOptions>();
  auto targets = std::make_shared<std::vector<std::string>>();
  auto scenes = std::make_shared<std::string>();
  CLI::App* sub =
      line.cli.add_subcommand("tune", "the cheapest settings that meet quality targets on every frame of your scenes");
  sub->add_option("--scenes", *scenes, "comma-separated scene files (default: default)");
  sub->add_option("--target", *targets, "psnr_db=X, edge_psnr_db=X, interior_psnr_db=X or ssim=X (repeatable)")
      ->required();
  sub->add_option("--cost", options->cost, "evals_per_pixel | gpu_ms | plugin_bytes_per_pixel");
  sub->add_option("--candidates", options->candidates,
                  "comma-separated method specs (default: 'grid', the registry's)");
  line.addSizeOptions(sub, options->width, options->height);
  addGroundTruthOption(sub, options->groundTruthSamples);
  sub->add_option("--frames", options->frames, "frames of each scene's path")->check(CLI::Range(1, 10000));
  sub->add_option("--out", options->out, "the config file to write (a report beside it: .md, .json)");
  sub->add_option("--cache", options->cache, "measured points, reused by later runs");
  line.commands.push_back({sub, [options, targets, scenes](const retroaa::Config&) {
                             for (const std::string& t : *targets) options->targets.push_back(app::parseTuneTarget(t));
                             if (!scenes->empty()) {
                               options->scenes.clear();
                               std::stringstream list(*scenes);
                               for (std::string s; std::getline(list, s, ',');) options->scenes.push_back(s);
                             }
                             return app::runTune(*options);
                           }});
}

void addConfig(CommandLine& line) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* sub = line.cli.add_subcommand("config", "list every config key with its default, range and effect");
  sub->add_flag("--markdown", *markdown, "as the Markdown table of docs/config.md");
  line.commands.push_back({sub, [markdown](const retroaa::Config&) {
                             std::printf("%s", app::configReference(*markdown).c_str());
                             return app::kExitOk;
                           }});
}

void addScore(CommandLine& line) {
  auto options = std::make_shared<app::ScoreOptions>();
  CLI::App* sub = line.cli.add_subcommand(
      "score", "a foreign engine's captured frames (one per method) against its supersampled reference render");
  sub->add_option("captures", options->captureDir, "folder with capture.jsonl and the captured PNGs")->required();
  sub->add_option("--reference", options->reference,
                  "the same frame rendered at --factor× width and height; for a sequence (records with a frame), "
                  "the folder of the reference's capture, matched frame by frame")
      ->required();
  sub->add_option("--factor", options->factor, "the reference's scale, box-filtered down in linear light")
      ->default_val(4);
  sub->add_option("--out", options->out, "folder for report.md, report.json and crops (default: the captures')");
  auto crops = std::make_shared<std::vector<std::string>>();
  auto regions = std::make_shared<std::vector<std::string>>();
  sub->add_option("--crop", *crops, "X,Y,SIZE: a square of capture pixels shown 4× for every method (repeatable)");
  sub->add_option("--region", *regions, "NAME=X,Y,W,H: a rectangle scored apart, e.g. kart=120,150,80,60 (repeatable)");
  line.commands.push_back({sub, [options, crops, regions](const retroaa::Config&) {
                             for (const std::string& crop : *crops) options->crops.push_back(app::parseCrop(crop));
                             for (const std::string& region : *regions)
                               options->regions.push_back(app::parseRegion(region));
                             return app::score(*options);
                           }});
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine line;
  line.cli.require_subcommand(1);
  for (auto add : {addRender, addBench, addRecord, addRegress, addSoak, addView, addTune, addConfig, addScore})
    add(line);
  try {
    line.cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = line.cli.exit(e);
    return code == 0 ? app::kExitOk : app::kExitBadInput;
  }
  try {
    const retroaa::Config config = line.config();
    for (const auto& [sub, run] : line.commands)
      if (sub->parsed()) return run(config);
    return app::kExitBadInput;
  } catch (const host::SceneError& e) {
    std::fprintf(stderr, "retroaa: bad input file: %s\n", e.what());
    return app::kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "retroaa: %s\n", e.what());
    return app::kExitBadInput;
  } catch (const host::ContextError& e) {
    std::fprintf(stderr, "retroaa: no usable OpenGL context: %s\n", e.what());
    return app::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "retroaa: error: %s\n", e.what());
    return app::kExitCheckFailed;
  }
}
