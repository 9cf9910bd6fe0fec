// Replays the fuzzing corpus (seeds and every crash or edge case fuzzing found) through the same entry
// points as the fuzzers: nothing crashes, and every rejection names the file and what was wrong.
#include "fuzz_entries.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

namespace {

std::vector<std::filesystem::path> corpus(const std::string& target) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RETROAA_FUZZ_CORPUS) + "/" + target))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

// Replays one corpus through `entry`; `checkRejection` judges each rejection's message.
struct Replayed {
  int accepted = 0, rejected = 0;
};
static Replayed replay(const std::string& target, fuzz::Outcome (*entry)(const uint8_t*, size_t),
                const std::function<void(const std::filesystem::path&, const std::string&)>& checkRejection) {
  Replayed counts;
  for (const auto& file : corpus(target)) {
    const std::string input = bytes(file);
    const fuzz::Outcome outcome = entry(reinterpret_cast<const uint8_t*>(input.data()), input.size());
    if (outcome.accepted) {
      ++counts.accepted;
      continue;
    }
    ++counts.rejected;
    checkRejection(file, outcome.message);
  }
  std::printf("%s corpus: %d accepted, %d rejected\n", target.c_str(), counts.accepted, counts.rejected);
  return counts;
}

TEST(FuzzCorpus, ScenesParseOrFailNamingFileAndField) {
  const Replayed counts = replay("scene", fuzz::sceneText, [](const auto& file, const std::string& message) {
    EXPECT_EQ(message.rfind("fuzz.json: ", 0), 0u) << file << ": " << message;
    EXPECT_TRUE(message.find(": $") != std::string::npos || message.find("(document)") != std::string::npos)
        << file << ": the message names no field: " << message;
  });
  EXPECT_GT(counts.accepted, 0);
  EXPECT_GT(counts.rejected, 0);
}

TEST(FuzzCorpus, ConfigsParseOrFailNamingSourceAndLine) {
  const Replayed counts = replay("config", fuzz::configText, [](const auto& file, const std::string& message) {
    EXPECT_EQ(message.rfind("fuzz.cfg:", 0), 0u) << file << ": " << message;
  });
  EXPECT_GT(counts.accepted, 0);
  EXPECT_GT(counts.rejected, 0);
}

TEST(FuzzCorpus, ModelsLoadOrFailNamingTheFile) {
  const Replayed counts = replay("model", fuzz::modelFile, [](const auto& file, const std::string& message) {
    EXPECT_NE(message.find("retroaa_fuzz_model_"), std::string::npos) << file << ": " << message;
  });
  EXPECT_GT(counts.accepted + counts.rejected, 0);
}
