// Contexts lacking a feature, simulated by masking it: the plugin falls back, says which and why,
// and nothing else changes.
#include "commands.h"
#include "test_support.h"

using namespace testing_support;

TEST(Capabilities, WithoutMultisamplingEveryMsaaMethodFallsBackToFxaa) {
  PatchedHost host("default", 96, 72);
  const app::DisplayImage fxaa = host.render("fxaa");
  for (const char* method : {"resolve", "edge", "per-sample", "adaptive", "aggregate", "coverage"}) {
    retroaa::Config config = app::parseMethodSpec(method, {}).config;
    auto hooks = installHooks(host, config, 0, 1);
    EXPECT_EQ(hooks->plugin().config().method, retroaa::Method::Fxaa) << method;
    const auto warnings = hooks->plugin().warnings();
    ASSERT_FALSE(warnings.empty()) << method;
    EXPECT_NE(warnings.back().find(std::string("method ") + method + " needs multisampling"), std::string::npos)
        << warnings.back();
    EXPECT_NE(warnings.back().find("GL_MAX_SAMPLES is 1; falling back to fxaa"), std::string::npos) << warnings.back();
    host.renderer->renderFrame(host.scene.camera);
    EXPECT_EQ(app::DisplayImage::fromRgba8(96, 72, host.renderer->readDisplay()).rgb, fxaa.rgb) << method;
    // fxaa's own: the display's copy (RGBA8) and the stencil marking the pixels it filters.
    EXPECT_EQ(hooks->plugin().stats().bytesHeld, 96u * 72u * (4u + 1u)) << "no MSAA storage for " << method;
  }
  host.renderer->setHooks(host.hooks.get());
}

TEST(Capabilities, FewerSamplesAreClampedWithAWarning) {
  PatchedHost host("default", 64, 48);
  retroaa::Config config;
  config.method = retroaa::Method::Edge;
  config.samples = 4;
  auto hooks = installHooks(host, config, 0, 2);
  EXPECT_EQ(hooks->plugin().config().samples, 2);
  EXPECT_NE(hooks->plugin().warnings().front().find("samples=4 requested, the context grants 2"), std::string::npos);
  host.renderer->renderFrame(host.scene.camera);  // still renders (llvmpipe may back 2 with 4)
  EXPECT_GE(hooks->plugin().waitForStats().evaluationsPerPixel(), 1.0);
  host.renderer->setHooks(host.hooks.get());
}

TEST(Capabilities, WithoutTimerQueriesNoPassTimesAndSaysSo) {
  PatchedHost host("default", 64, 48);
  retroaa::Config config;
  config.method = retroaa::Method::Resolve;
  config.measureGpuTime = true;
  auto hooks = installHooks(host, config, retroaa::kFeatureTimerQuery, 0);
  host.renderer->renderFrame(host.scene.camera);
  EXPECT_TRUE(hooks->plugin().waitForStats().passes.empty());
  bool said = false;
  for (const std::string& w : hooks->plugin().warnings())
    said = said || w.find("no timer queries") != std::string::npos;
  EXPECT_TRUE(said);
  // And with them, the same config measures its passes.
  auto measured = installHooks(host, config, 0, 0);
  host.renderer->renderFrame(host.scene.camera);
  EXPECT_FALSE(measured->plugin().waitForStats().passes.empty());
  host.renderer->setHooks(host.hooks.get());
}

TEST(Plugins, TwoInstancesInOneProcessWorkSideBySide) {
  // Two views, two plugins with different methods, rendering alternately: each gives exactly what it
  // gives alone.
  PatchedHost left("default", 96, 72), right("default", 96, 72);
  const app::DisplayImage edgeAlone = left.render("edge");
  const app::DisplayImage aggregateAlone = right.render("aggregate");
  for (int i = 0; i < 3; ++i) {
    left.renderer->renderFrame(left.scene.camera);
    right.renderer->renderFrame(right.scene.camera);
  }
  EXPECT_EQ(app::DisplayImage::fromRgba8(96, 72, left.renderer->readDisplay()).rgb, edgeAlone.rgb);
  EXPECT_EQ(app::DisplayImage::fromRgba8(96, 72, right.renderer->readDisplay()).rgb, aggregateAlone.rgb);
}

TEST(Capabilities, AGBufferOverItsBudgetIsRefusedBeforeAnythingIsAllocated) {
  // 64 x 48 x 4 samples x the host's 40 B a sample = 480 KiB against a budget of 256 KiB: refused at create
  // and at reconfigure, naming the size and the budget; the context raises no GL_OUT_OF_MEMORY and the plugin
  // holds nothing. Within the budget the same method runs.
  PatchedHost host("default", 64, 48);
  retroaa::Description description;
  description.layout = patch::describeHostGBuffer(host.renderer->targets());
  description.gbufferBudgetBytes = 256 << 10;
  ASSERT_TRUE(retroaa::applyMethodSpec(description.config, "edge"));
  const auto refused = retroaa::Plugin::create(description);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().code, retroaa::ErrorCode::InvalidConfig);
  EXPECT_NE(refused.error().message.find("64 x 48 x 4 samples x 40 B"), std::string::npos) << refused.error().message;
  EXPECT_NE(refused.error().message.find("over its budget of 256 KiB"), std::string::npos) << refused.error().message;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  description.config = retroaa::Config{};  // off: nothing multisampled
  auto created = retroaa::Plugin::create(description);
  ASSERT_TRUE(created);
  retroaa::Config edge;
  ASSERT_TRUE(retroaa::applyMethodSpec(edge, "edge"));
  const retroaa::Status status = created.value()->reconfigure(edge);
  ASSERT_FALSE(status);
  EXPECT_NE(status.error().message.find("over its budget"), std::string::npos) << status.error().message;
  EXPECT_EQ(created.value()->stats().bytesHeld, 0u);
  description.gbufferBudgetBytes = 1 << 20;
  auto within = retroaa::Plugin::create(description);
  ASSERT_TRUE(within);
  EXPECT_TRUE(within.value()->reconfigure(edge));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
