// Config parsing: every bad input names the key, the value and what is allowed; nothing half-applies.
#include "retroaa/config.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

using namespace retroaa;

TEST(Config, DefaultsAreDocumentedOnce) {
  const Config defaults;
  Config parsed;
  for (const ConfigKey& key : configKeys()) ASSERT_TRUE(applySetting(parsed, key.name, key.defaultValue)) << key.name;
  EXPECT_EQ(toConfigText(parsed), toConfigText(defaults));
}

// A key names the methods that read it (the viewer shows it for each): the technique that declares it
// and those that read it too; a shared key names none.
TEST(Config, EachKeyNamesTheMethodsThatReadIt) {
  std::map<std::string, std::vector<std::string>> readers;
  for (const ConfigKey& key : configKeys()) readers[key.name].assign(key.methods.begin(), key.methods.end());
  using Names = std::vector<std::string>;
  EXPECT_EQ(readers.at("samples"), Names{});
  EXPECT_EQ(readers.at("budget_ms"), Names{});
  EXPECT_EQ(readers.at("adaptive_min_samples"), Names{"adaptive"});
  EXPECT_EQ(readers.at("edge_detector"), Names{"edge"});
  // Every method on the MSAA G-buffer runs the resolve: the G-buffer's source and the resolve's keys.
  for (const char* key : {"closeness", "supersample", "resolve_weighting"}) {
    const Names& methods = readers.at(key);
    for (const MethodInfo& row : methodTable()) {
      const bool reads = std::find(methods.begin(), methods.end(), row.name) != methods.end();
      EXPECT_EQ(reads, usesMsaa(row.method)) << key << " and " << row.name;
    }
  }
  EXPECT_EQ(readers.at("smaa_quality"), (Names{"smaa", "smaa-s2x"}));  // SMAA S2x runs SMAA 1x
  for (const MethodInfo& row : methodTable()) {  // a stacking switch belongs to the method it stacks
    if (*row.stackKey) {
      EXPECT_EQ(readers.at(row.stackKey), Names{row.name});
    }
  }
}

// What a capture waits for: nothing without a history; with one, two rounds of the jitter sequence and
// long enough for the blend to forget its first frame.
TEST(Config, OnlyAMethodWithAHistoryTakesFramesToConverge) {
  auto framesOf = [](const std::string& spec) {
    Config config;
    EXPECT_TRUE(applyMethodSpec(config, spec)) << spec;
    return historyFrames(config);
  };
  EXPECT_EQ(framesOf("off"), 0);
  EXPECT_EQ(framesOf("resolve"), 0);
  EXPECT_EQ(framesOf("temporal"), 40) << "4 / temporal_blend (0.1), beyond 2 rounds of 8";
  EXPECT_EQ(framesOf("resolve+temporal@temporal_jitter_length=32"), 64);
}

TEST(Config, UnknownKeyNamesKnownKeys) {
  Config config;
  const Status status = applySetting(config, "metod", "resolve");
  ASSERT_FALSE(status);
  EXPECT_EQ(status.error().code, ErrorCode::InvalidConfig);
  EXPECT_NE(status.error().message.find("unknown config key 'metod'"), std::string::npos);
  EXPECT_NE(status.error().message.find("method"), std::string::npos);
}

TEST(Config, BadValuesNameKeyValueAndAllowedSet) {
  Config config;
  Status s = applySetting(config, "method", "taa");
  EXPECT_NE(s.error().message.find("'method': unknown value 'taa' (allowed: off, fxaa, smaa, resolve"),
            std::string::npos)
      << s.error().message;
  s = applySetting(config, "samples", "3");
  EXPECT_NE(s.error().message.find("'samples': unsupported value '3' (allowed: 1, 2, 4, 8, 16)"), std::string::npos);
  s = applySetting(config, "closeness", "1e9");
  EXPECT_NE(s.error().message.find("'closeness': value '1e9' is not a number in [0, 100]"), std::string::npos);
  s = applySetting(config, "closeness", "nan");
  EXPECT_FALSE(s);
  s = applySetting(config, "fxaa", "maybe");
  EXPECT_NE(s.error().message.find("(allowed: on, off)"), std::string::npos);
}

TEST(Config, TextNamesTheLineAndLeavesTheConfigUntouchedOnError) {
  Config config;
  config.closeness = 7;
  const Status s = applyConfigText(config, "# comment\nmethod = resolve\nsamples=5\n", "my.cfg");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("my.cfg:3:"), std::string::npos) << s.error().message;
  EXPECT_EQ(config.method, Method::Off);
  EXPECT_EQ(config.closeness, 7);
  EXPECT_NE(applyConfigText(config, "just words", "x.cfg").error().message.find("x.cfg:1: expected 'key=value'"),
            std::string::npos);
}

TEST(Config, RoundTripsThroughText) {
  Config config;
  ASSERT_TRUE(
      applySettingsList(config, "method=resolve, samples=2; resolve_weighting=fso,closeness=2.5,fxaa=on", "env"));
  Config reread;
  ASSERT_TRUE(applyConfigText(reread, toConfigText(config), "roundtrip"));
  EXPECT_EQ(toConfigText(reread), toConfigText(config));
  EXPECT_EQ(reread.resolveWeighting, ResolveWeighting::Fso);
  EXPECT_EQ(reread.samples, 2);
  EXPECT_TRUE(reread.fxaa);
}

TEST(Config, FreeSpaceOpenFlags) {
  Config config;
  std::vector<std::string> warnings;
  ASSERT_TRUE(applyFsoFlag(config, "-msaa", "8", warnings));
  EXPECT_EQ(config.method, Method::Resolve);
  EXPECT_EQ(config.samples, 8);
  ASSERT_TRUE(applyFsoFlag(config, "-aa_preset", "1", warnings));
  EXPECT_TRUE(config.fxaa);
  EXPECT_EQ(config.fxaaQuality, FxaaQuality::Medium);
  EXPECT_TRUE(warnings.empty());

  Config other;  // preset first, then msaa: both survive
  ASSERT_TRUE(applyFsoFlag(other, "-aa_preset", "2", warnings));
  EXPECT_EQ(other.method, Method::Fxaa);
  ASSERT_TRUE(applyFsoFlag(other, "-msaa", "4", warnings));
  EXPECT_EQ(other.method, Method::Resolve);
  EXPECT_TRUE(other.fxaa);

  ASSERT_TRUE(applyFsoFlag(config, "-msaa", "6", warnings));  // FSO: warn and use 0
  EXPECT_EQ(config.method, Method::Off);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("-msaa 6"), std::string::npos);
  ASSERT_TRUE(applyFsoFlag(config, "-aa_preset", "5", warnings));  // SMAA high, as in FSO
  EXPECT_EQ(warnings.size(), 1u);
  EXPECT_EQ(config.method, Method::Smaa);
  EXPECT_EQ(config.smaaQuality, SmaaQuality::High);
  ASSERT_TRUE(applyFsoFlag(config, "-msaa", "4", warnings));  // preset first, then msaa: SMAA stacks on resolve
  EXPECT_EQ(config.method, Method::Resolve);
  EXPECT_TRUE(config.smaa);
  EXPECT_FALSE(config.fxaa);
  ASSERT_TRUE(applyFsoFlag(config, "-aa_preset", "0", warnings));  // the last preset wins: one post filter
  EXPECT_TRUE(config.fxaa);
  EXPECT_FALSE(config.smaa);
  EXPECT_EQ(config.fxaaQuality, FxaaQuality::Low);
  EXPECT_FALSE(applyFsoFlag(config, "-aa_preset", "9", warnings));
  EXPECT_FALSE(applyFsoFlag(config, "-msaa", "four", warnings));
  EXPECT_FALSE(applyFsoFlag(config, "-smaa", "1", warnings));

  Config postProcess;  // FSO: -post_process_aa alone is SMAA low; a preset, in either order, wins
  ASSERT_TRUE(applyFsoFlag(postProcess, "-post_process_aa", "", warnings));
  EXPECT_EQ(postProcess.method, Method::Smaa);
  EXPECT_EQ(postProcess.smaaQuality, SmaaQuality::Low);
  ASSERT_TRUE(applyFsoFlag(postProcess, "-aa_preset", "1", warnings));
  EXPECT_EQ(postProcess.method, Method::Fxaa);
  ASSERT_TRUE(applyFsoFlag(postProcess, "-post_process_aa", "", warnings));
  EXPECT_EQ(postProcess.method, Method::Fxaa);
  EXPECT_EQ(postProcess.fxaaQuality, FxaaQuality::Medium);
}

TEST(Config, PresetsApplyTheirTunedBundleAndLaterKeysOverride) {
  for (const char* name : {"low", "medium", "high", "ultra"}) {
    Config fromPreset;
    ASSERT_TRUE(applySetting(fromPreset, "preset", name)) << name;
    Config fromFile;
    ASSERT_TRUE(applyConfigFile(fromFile, std::string(RETROAA_SOURCE_DIR) + "/presets/" + name + ".cfg")) << name;
    EXPECT_EQ(toConfigText(fromPreset), toConfigText(fromFile)) << name;
  }
  Config config;
  config.shaderOverrideDirectory = "mods/shaders";
  ASSERT_TRUE(applyConfigText(config, "preset=high\nsamples=2\n", "user.cfg"));
  EXPECT_EQ(config.samples, 2);                               // a later key overrides the preset
  EXPECT_EQ(config.shaderOverrideDirectory, "mods/shaders");  // not a quality key: left alone
  EXPECT_FALSE(applySetting(config, "preset", "extreme"));
}

// The budget controller on a simulated cost model: time = load + 6 · s / (1 + s) ms for quality scale s
// (monotonic, saturating, like refinement on a real scene). Deterministic: no GPU involved.
#include "budget_controller.h"

#include <cmath>

TEST(BudgetController, ConvergesAfterAStepInLoadAndHoldsWithinFifteenPercent) {
  BudgetController controller(5.0);
  double load = 1.0, scale = controller.scale();
  std::vector<double> times;
  for (int frame = 0; frame < 160; ++frame) {
    if (frame == 80) load = 3.0;  // a step change: something else now eats 2 ms more
    const double ms = load + 6.0 * scale / (1.0 + scale);
    times.push_back(ms);
    scale = controller.update(ms);
  }
  auto within = [&](int from, int to) {
    for (int f = from; f < to; ++f)
      if (std::fabs(times[f] - 5.0) > 0.15 * 5.0) return false;
    return true;
  };
  int settle = 0, settleAfterStep = 0;
  for (int f = 0; f < 80 && !within(f, 80); ++f) settle = f + 1;
  for (int f = 80; f < 160 && !within(f, 160); ++f) settleAfterStep = f + 1 - 80;
  std::printf("budget 5 ms: settled within %d frames from start, %d frames after the step\n", settle, settleAfterStep);
  EXPECT_LE(settle, 20);
  EXPECT_LE(settleAfterStep, 20);
  // No oscillation in steady state: the time crosses the budget at most twice in the last 40 frames.
  int crossings = 0;
  for (int f = 121; f < 160; ++f) crossings += (times[f] - 5.0) * (times[f - 1] - 5.0) < 0;
  EXPECT_LE(crossings, 2);
  EXPECT_NEAR(controller.scale(), 0.5, 0.25);  // load 3: 3 + 6 s / (1 + s) = 5 at s = 0.5
}

TEST(BudgetController, IgnoresNonsenseAndStaysInBounds) {
  BudgetController controller(2.0);
  for (int i = 0; i < 500; ++i) controller.update(1000.0);
  EXPECT_DOUBLE_EQ(controller.scale(), BudgetController::kMinScale);
  const double before = controller.scale();
  controller.update(std::nan(""));
  controller.update(-1.0);
  EXPECT_DOUBLE_EQ(controller.scale(), before);
  for (int i = 0; i < 500; ++i) controller.update(0.0);
  EXPECT_DOUBLE_EQ(controller.scale(), BudgetController::kMaxScale);
}

TEST(Config, EnumeratedKeysListTheirValuesAndReadBack) {
  const std::vector<std::string> weightings = settingValues("resolve_weighting");
  ASSERT_EQ(weightings.size(), 6u);
  for (const std::string& value : weightings) {
    Config config;
    ASSERT_TRUE(applySetting(config, "resolve_weighting", value)) << value;
    EXPECT_EQ(readSetting(config, "resolve_weighting"), value);
  }
  EXPECT_EQ(settingValues("samples"), (std::vector<std::string>{"1", "2", "4", "8", "16"}));
  EXPECT_EQ(settingValues("fxaa"), (std::vector<std::string>{"on", "off"}));
  EXPECT_EQ(settingValues("method").size(), methodTable().size());
  EXPECT_TRUE(settingValues("closeness").empty());
  EXPECT_TRUE(settingValues("shader_override_dir").empty());
  EXPECT_TRUE(settingValues("no_such_key").empty());
  EXPECT_EQ(readSetting(Config{}, "no_such_key"), "");
}

TEST(Config, ValidationRefusesWhatTheParserRefusesAndNothingElse) {
  Config config;
  EXPECT_TRUE(validateConfig(config));
  config.closeness = 100.0f;  // the range's end is inside
  EXPECT_TRUE(validateConfig(config));
  config.closeness = 100.001f;
  const Status status = validateConfig(config);
  ASSERT_FALSE(status);
  EXPECT_EQ(status.error().code, ErrorCode::InvalidConfig);
  EXPECT_NE(status.error().message.find("'closeness'"), std::string::npos) << status.error().message;
}

TEST(Config, AConfigFileOverOneMebibyteIsRefusedNamingItsSize) {
  const std::string path = (std::filesystem::temp_directory_path() / "retroaa_big.cfg").string();
  {
    std::ofstream out(path);
    const std::string line(1023, '#');
    for (int i = 0; i < 1100; ++i) out << line << "\n";  // comments only: valid, but 1 126 400 bytes
  }
  Config config;
  const Status status = applyConfigFile(config, path);
  ASSERT_FALSE(status);
  EXPECT_EQ(status.error().code, ErrorCode::InvalidConfig);
  EXPECT_NE(
      status.error().message.find(path + ": cannot open config file: it is 1126400 bytes, more than the 1 MiB allowed"),
      std::string::npos)
      << status.error().message;
  std::filesystem::remove(path);
}

TEST(Config, MessagesQuoteUserInputShortAndEscaped) {
  Config config;
  const std::string huge = "method=" + std::string(10u << 20, 'x');  // a 10 MB line
  Status status = applyConfigText(config, huge, "big.cfg");
  ASSERT_FALSE(status);
  EXPECT_LT(status.error().message.size(), 400u) << status.error().message.substr(0, 400);
  EXPECT_NE(status.error().message.find("(10485760 bytes, first 80 shown)"), std::string::npos)
      << status.error().message;

  const std::string binary = std::string("\x01\x02\x1b[31m\xff", 8) + "=1";  // control bytes, an escape sequence
  status = applyConfigText(config, binary, "binary.cfg");
  ASSERT_FALSE(status);
  for (char c : status.error().message)
    EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "raw byte " << int(c) << " in the message";
  EXPECT_NE(status.error().message.find("'\\x01\\x02\\x1b[31m\\xff'"), std::string::npos) << status.error().message;
}

TEST(Config, AMethodSpecSetsTheMethodWeightingStackedFiltersAndSettings) {
  Config config;
  ASSERT_TRUE(applyMethodSpec(config, "resolve/fso+fxaa+coverage@samples=8@closeness=3"));
  EXPECT_EQ(config.method, Method::Resolve);
  EXPECT_EQ(config.resolveWeighting, ResolveWeighting::Fso);
  EXPECT_TRUE(config.fxaa);
  EXPECT_TRUE(config.coverageFilter);
  EXPECT_EQ(config.samples, 8);
  EXPECT_FLOAT_EQ(config.closeness, 3.0f);
  Config plain;
  ASSERT_TRUE(applyMethodSpec(plain, "edge"));
  EXPECT_EQ(plain.method, Method::Edge);
  EXPECT_FALSE(plain.fxaa);
}

TEST(Config, ABadMethodSpecNamesTheSpecAndItsBadPart) {
  struct Case {
    const char* spec;
    const char* named;
  };
  for (const Case& c :
       {Case{"resolve+nope", "can be stacked"}, Case{"edge@samples", "expected key=value"},
        Case{"edge@samples=3", "samples"}, Case{"resolve/sideways", "sideways"}, Case{"blurry", "blurry"}}) {
    Config config;
    const Status status = applyMethodSpec(config, c.spec);
    ASSERT_FALSE(status) << c.spec;
    EXPECT_EQ(status.error().code, ErrorCode::InvalidConfig) << c.spec;
    EXPECT_NE(status.error().message.find(std::string("method '") + c.spec + "'"), std::string::npos)
        << status.error().message;
    EXPECT_NE(status.error().message.find(c.named), std::string::npos) << status.error().message;
  }
}
