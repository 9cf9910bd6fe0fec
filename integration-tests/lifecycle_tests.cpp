// The plugin's lifecycle (plugin/src/lifecycle.cpp): what a plugin holds after a reconfigure depends on
// the config it reaches, never on the one it left.
#include "commands.h"
#include "test_support.h"

#include <map>

using namespace testing_support;

namespace {

// One spec per shape of what a plugin holds: nothing, a post target, the MSAA G-buffer and resolve,
// slices (with a detector, metrics, clusters, SMAA per slice, every sample, a supersampled G-buffer),
// a prepass, a history, stacked filters, and the same methods at another sample count.
const char* const kSpecs[] = {"off",
                              "fxaa",
                              "smaa",
                              "resolve",
                              "resolve+fxaa",
                              "edge",
                              "per-sample",
                              "adaptive",
                              "aggregate",
                              "smaa-s2x",
                              "coverage",
                              "reconstruct",
                              "temporal",
                              "resolve+temporal",
                              "edge@samples=2",
                              "ssaa@supersample=2"};

struct Held {
  uint64_t bytes = 0;
  int glObjects = 0;
  std::vector<float> rgb;  // the frame after the switch (methods without a history)
};

Held heldAfter(PatchedHost& host, const std::string& spec) {
  const app::DisplayImage image = host.render(spec);
  const retroaa::Stats stats = host.hooks->plugin().stats();
  Held held;
  held.bytes = stats.bytesHeld;
  held.glObjects = stats.glObjectsHeld;
  held.rgb = image.rgb;
  return held;
}

bool keepsAHistory(const std::string& spec) { return spec.find("temporal") != std::string::npos; }

}  // namespace

// Every ordered pair (A, B): a plugin reconfigured from A to B holds the bytes and GL objects a plugin
// reconfigured from off to B holds (off holds nothing: what B alone needs), and renders B's frame byte
// for byte (a history's first frame depends on the frame count, so only its holdings are compared). The
// plugin ends where it began, with no GL error.
TEST(Lifecycle, EveryReconfigureOrderHoldsWhatTheNewConfigNeedsAndNothingElse) {
  PatchedHost host("default", 48, 32);
  const int errorsBefore = context().debugErrorCount();
  host.render("off");
  const int objectsAtStart = host.hooks->plugin().stats().glObjectsHeld;
  std::map<std::string, Held> fromOff;
  for (const char* spec : kSpecs) {
    fromOff[spec] = heldAfter(host, spec);
    host.render("off");
  }
  int pairs = 0;
  for (const char* from : kSpecs)
    for (const char* to : kSpecs) {
      if (std::string(from) == to) continue;
      host.render(from);
      const Held held = heldAfter(host, to);
      const Held& expected = fromOff[to];
      EXPECT_EQ(held.bytes, expected.bytes) << from << " -> " << to;
      EXPECT_EQ(held.glObjects, expected.glObjects) << from << " -> " << to;
      if (!keepsAHistory(to)) {
        EXPECT_TRUE(held.rgb == expected.rgb) << from << " -> " << to << ": another image";
      }
      ++pairs;
    }
  EXPECT_EQ(pairs, 16 * 15);
  host.render("off");
  EXPECT_EQ(host.hooks->plugin().stats().glObjectsHeld, objectsAtStart);
  EXPECT_EQ(host.hooks->plugin().stats().bytesHeld, 0u);
  EXPECT_EQ(context().debugErrorCount(), errorsBefore);
}

// A config the parser's rules refuse: the plugin keeps running the config it had, holding what that
// config needs.
TEST(Lifecycle, AReconfigureTheContextRefusesKeepsThePreviousConfigsHoldings) {
  PatchedHost host("default", 48, 32);
  const Held edge = heldAfter(host, "edge");
  retroaa::Config bad = host.hooks->plugin().config();
  bad.samples = 3;  // no such sample count: refused by validation before anything is freed
  EXPECT_FALSE(host.hooks->plugin().reconfigure(bad));
  EXPECT_EQ(host.hooks->plugin().config().method, retroaa::Method::Edge);
  EXPECT_EQ(host.hooks->plugin().stats().bytesHeld, edge.bytes);
  EXPECT_EQ(host.hooks->plugin().stats().glObjectsHeld, edge.glObjects);
}
