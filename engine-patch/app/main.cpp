// `retroaa`: render, bench (more subcommands land with their issues). Exit codes: 0 ok, 1 a check
// failed, 2 bad usage or input (with a message naming what was wrong).
#include "commands.h"
#include "regress.h"
#include "tune.h"
#ifdef RETROAA_HAS_VIEWER
#include "viewer.h"
#endif
#include "headless_context.h"
#include "scene.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace {

// --config FILE, --set key=value, -msaa N, -aa_preset N and RETROAA_SETTINGS, in that order of
// precedence from lowest: environment, file, FSO flags, --set.
retroaa::Config buildConfig(const std::string& configFile, const std::vector<std::string>& sets,
                            const std::string& msaa, const std::string& aaPreset) {
  retroaa::Config config;
  auto check = [](const retroaa::Status& status) {
    if (!status) throw std::invalid_argument(status.error().message);
  };
  if (const char* env = std::getenv("RETROAA_SETTINGS")) check(retroaa::applySettingsList(config, env, "RETROAA_SETTINGS"));
  if (!configFile.empty()) check(retroaa::applyConfigFile(config, configFile));
  std::vector<std::string> warnings;
  if (!msaa.empty()) check(retroaa::applyFsoFlag(config, "-msaa", msaa, warnings));
  if (!aaPreset.empty()) check(retroaa::applyFsoFlag(config, "-aa_preset", aaPreset, warnings));
  for (const std::string& w : warnings) std::fprintf(stderr, "retroaa: warning: %s\n", w.c_str());
  for (const std::string& set : sets) {
    const size_t equals = set.find('=');
    if (equals == std::string::npos) throw std::invalid_argument("--set expects key=value, got '" + set + "'");
    check(retroaa::applySetting(config, set.substr(0, equals), set.substr(equals + 1)));
  }
  return config;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"retroaa: retrofit anti-aliasing for deferred renderers"};
  cli.require_subcommand(1);
  std::string configFile, msaa, aaPreset, samples;
  std::vector<std::string> sets;
  auto addSizeOptions = [](CLI::App* sub, int& width, int& height) {
    sub->add_option("--width", width)->check(CLI::Range(16, 8192));
    sub->add_option("--height", height)->check(CLI::Range(16, 8192));
  };
  auto addConfigOptions = [&](CLI::App* sub) {
    sub->add_option("--config", configFile, "config file of key=value lines");
    sub->add_option("--set", sets, "one setting, key=value (repeatable)");
    sub->add_option("--samples", samples, "MSAA samples (same as --set samples=N)");
    sub->add_option("-m,--msaa", msaa, "FreeSpace Open's -msaa 0|4|8|16");
    sub->add_option("--aa_preset", aaPreset, "FreeSpace Open's -aa_preset 0..6");
  };

  app::RenderOptions render;
  CLI::App* renderCmd = cli.add_subcommand("render", "render one frame headless");
  renderCmd->add_option("--scene", render.scene, "scene file, or 'default'");
  renderCmd->add_option("--method", render.method, "method[/weighting][+fxaa][@key=value], or ground-truth (default: the config's)");
  addSizeOptions(renderCmd, render.width, render.height);
  renderCmd->add_option("--frame", render.frame, "camera path frame (default: the scene camera)");
  renderCmd->add_option("--gt-samples", render.groundTruthSamples, "ground truth supersamples per axis")->check(CLI::Range(1, 32));
  renderCmd->add_option("--out", render.out, "output image (.png display, .exr linear radiance)")->required();
  renderCmd->add_option("--heatmap", render.heatmap, "also write the error against ground truth as a heat map");
  renderCmd->add_option("--show", render.show, "write a visualisation instead: edges | samples | aggregates (lighting evaluations per pixel)");
  addConfigOptions(renderCmd);

  app::BenchOptions bench;
  CLI::App* benchCmd = cli.add_subcommand("bench", "every method on one frame: speed against error");
  benchCmd->add_option("--scene", bench.scene, "scene file, or 'default'");
  benchCmd->add_option("--methods", bench.methods, "comma-separated method specs, or 'all'");
  addSizeOptions(benchCmd, bench.width, bench.height);
  benchCmd->add_option("--frame", bench.frame, "camera path frame (default: the scene camera)");
  benchCmd->add_option("--gt-samples", bench.groundTruthSamples, "ground truth supersamples per axis")->check(CLI::Range(1, 32));
  benchCmd->add_option("--repeats", bench.repeats, "timed frames per method (median)")->check(CLI::Range(1, 100));
  benchCmd->add_option("--json", bench.json, "write the rows as JSON");
  benchCmd->add_option("--csv", bench.csv, "write the rows as CSV");
  benchCmd->add_option("--report", bench.report, "write a Markdown report");
  benchCmd->add_option("--images", bench.imagesDirectory, "write each method's image and error heat map here");
  addConfigOptions(benchCmd);

  app::RecordOptions record;
  CLI::App* recordCmd = cli.add_subcommand("record", "record a camera path for a scene (an orbit and dolly; no window)");
  recordCmd->add_option("--scene", record.scene, "scene file, or 'default'");
  recordCmd->add_option("--orbit-degrees", record.orbitDegrees, "orbit about the camera target")->check(CLI::Range(-720.0, 720.0));
  recordCmd->add_option("--dolly", record.dolly, "final distance as a multiple of the first")->check(CLI::Range(0.01, 100.0));
  recordCmd->add_option("--seconds", record.seconds, "length")->check(CLI::Range(0.01, 3600.0));
  recordCmd->add_option("--fps", record.framesPerSecond, "playback frame rate")->check(CLI::Range(1.0, 1000.0));
  recordCmd->add_option("--keys", record.keys, "keys along the path")->check(CLI::Range(2, 1000));
  recordCmd->add_option("--out", record.out, "camera path file (JSON)")->required();

  app::RegressOptions regress;
  CLI::App* regressCmd = cli.add_subcommand("regress", "every frame of recorded demo scenes with every method: report and goldens");
  regressCmd->add_option("scenes", regress.scenes, "scene files (default: the five recorded scenes)");
  regressCmd->add_option("--methods", regress.methods, "comma-separated method specs, or 'all'");
  addSizeOptions(regressCmd, regress.width, regress.height);
  regressCmd->add_option("--gt-samples", regress.groundTruthSamples, "ground truth supersamples per axis")->check(CLI::Range(1, 32));
  regressCmd->add_option("--stride", regress.frameStride, "every n-th frame of each path")->check(CLI::Range(1, 1000));
  regressCmd->add_option("--frames", regress.maxFrames, "at most this many frames per scene (0: all)")->check(CLI::Range(0, 100000));
  regressCmd->add_option("--out", regress.out, "report folder");
  regressCmd->add_option("--golden-dir", regress.goldenDirectory, "where the goldens live");
  regressCmd->add_flag("--check", regress.check, "compare with the goldens; exit 1 naming each figure that got worse");
  regressCmd->add_flag("--update-golden", regress.updateGolden, "rewrite the goldens from this run");
  addConfigOptions(regressCmd);

  app::SoakOptions soak;
  CLI::App* soakCmd = cli.add_subcommand("soak", "many frames switching every setting: leaks, GL errors, memory");
  soakCmd->add_option("--frames", soak.frames)->check(CLI::Range(1, 10000000));
  addSizeOptions(soakCmd, soak.width, soak.height);
  soakCmd->add_option("--max-growth-mib", soak.maxGrowthMiB, "allowed resident memory growth after warm-up");

#ifdef RETROAA_HAS_VIEWER
  app::ViewOptions view;
  CLI::App* viewCmd = cli.add_subcommand("view", "the interactive viewer (GLFW window, Dear ImGui panel)");
  viewCmd->add_option("--scene", view.scene, "scene file, or 'default'");
  viewCmd->add_option("--method", view.method, "method A (left side)");
  viewCmd->add_option("--compare", view.compare, "method B: split screen with a draggable divider");
  addSizeOptions(viewCmd, view.width, view.height);
  viewCmd->add_option("--script", view.script, "timed actions with a fixed time step (docs/viewer.md)");
  viewCmd->add_option("--record-path", view.recordPath, "where R writes the recorded camera path");
  addConfigOptions(viewCmd);
#endif

  app::TuneOptions tune;
  std::vector<std::string> tuneTargets;
  std::string tuneScenes;
  CLI::App* tuneCmd = cli.add_subcommand("tune", "the cheapest settings that meet quality targets on every frame of your scenes");
  tuneCmd->add_option("--scenes", tuneScenes, "comma-separated scene files (default: default)");
  tuneCmd->add_option("--target", tuneTargets, "psnr=X, edge_psnr=X or ssim=X (repeatable)")->required();
  tuneCmd->add_option("--cost", tune.cost, "evals | gpu_ms | memory");
  tuneCmd->add_option("--candidates", tune.candidates, "comma-separated method specs (default: the built-in grid)");
  addSizeOptions(tuneCmd, tune.width, tune.height);
  tuneCmd->add_option("--gt-samples", tune.groundTruthSamples)->check(CLI::Range(1, 32));
  tuneCmd->add_option("--frames", tune.frames, "frames of each scene's path")->check(CLI::Range(1, 10000));
  tuneCmd->add_option("--out", tune.out, "the config file to write (a report beside it: .md, .json)");
  tuneCmd->add_option("--cache", tune.cache, "measured points, reused by later runs");

  bool markdown = false;
  CLI::App* configCmd = cli.add_subcommand("config", "list every config key with its default, range and effect");
  configCmd->add_flag("--markdown", markdown, "as the Markdown table of docs/config.md");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? app::kExitOk : app::kExitBadInput;
  }
  try {
    if (!samples.empty()) sets.insert(sets.begin(), "samples=" + samples);
    const retroaa::Config config = buildConfig(configFile, sets, msaa, aaPreset);
    if (configCmd->parsed()) {
      std::printf("%s", app::configReference(markdown).c_str());
      return app::kExitOk;
    }
    if (recordCmd->parsed()) return app::runRecord(record);
    if (soakCmd->parsed()) return app::runSoak(soak);
    if (tuneCmd->parsed()) {
      for (const std::string& t : tuneTargets) tune.targets.push_back(app::parseTuneTarget(t));
      if (!tuneScenes.empty()) {
        tune.scenes.clear();
        std::stringstream list(tuneScenes);
        for (std::string s; std::getline(list, s, ',');) tune.scenes.push_back(s);
      }
      return app::runTune(tune);
    }
#ifdef RETROAA_HAS_VIEWER
    if (viewCmd->parsed()) {
      view.base = config;
      return app::runView(view);
    }
#endif
    if (regressCmd->parsed()) {
      regress.base = config;
      return app::runRegress(regress);
    }
    if (renderCmd->parsed()) {
      render.base = config;
      return app::runRender(render);
    }
    bench.base = config;
    return app::runBench(bench);
  } catch (const host::SceneError& e) {
    std::fprintf(stderr, "retroaa: bad scene: %s\n", e.what());
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
