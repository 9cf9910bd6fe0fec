// Replays the fuzzing corpus (seeds and every crash or edge case fuzzing found) through the same entry
// points as the fuzzers: nothing crashes, and every rejection names the file and what was wrong.
#include "fuzz_entries.h"

#include <gtest/gtest.h>

#include <filesystem>
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

TEST(FuzzCorpus, ScenesParseOrFailNamingFileAndField) {
  int accepted = 0, rejected = 0;
  for (const auto& file : corpus("scene")) {
    const std::string input = bytes(file);
    const fuzz::Outcome outcome = fuzz::sceneText(reinterpret_cast<const uint8_t*>(input.data()), input.size());
    if (outcome.accepted) {
      ++accepted;
      continue;
    }
    ++rejected;
    EXPECT_EQ(outcome.message.rfind("fuzz.json: ", 0), 0u) << file << ": " << outcome.message;
    EXPECT_TRUE(outcome.message.find(": $") != std::string::npos || outcome.message.find("(document)") != std::string::npos)
        << file << ": the message names no field: " << outcome.message;
  }
  std::printf("scene corpus: %d accepted, %d rejected\n", accepted, rejected);
  EXPECT_GT(accepted, 0);
  EXPECT_GT(rejected, 0);
}

TEST(FuzzCorpus, ConfigsParseOrFailNamingSourceAndLine) {
  int accepted = 0, rejected = 0;
  for (const auto& file : corpus("config")) {
    const std::string input = bytes(file);
    const fuzz::Outcome outcome = fuzz::configText(reinterpret_cast<const uint8_t*>(input.data()), input.size());
    if (outcome.accepted) {
      ++accepted;
      continue;
    }
    ++rejected;
    EXPECT_EQ(outcome.message.rfind("fuzz.cfg:", 0), 0u) << file << ": " << outcome.message;
  }
  std::printf("config corpus: %d accepted, %d rejected\n", accepted, rejected);
  EXPECT_GT(accepted, 0);
  EXPECT_GT(rejected, 0);
}

TEST(FuzzCorpus, ModelsLoadOrFailNamingTheFile) {
  int accepted = 0, rejected = 0;
  for (const auto& file : corpus("model")) {
    const std::string input = bytes(file);
    const fuzz::Outcome outcome = fuzz::modelFile(reinterpret_cast<const uint8_t*>(input.data()), input.size());
    if (outcome.accepted) {
      ++accepted;
      continue;
    }
    ++rejected;
    EXPECT_NE(outcome.message.find("retroaa_fuzz_model_"), std::string::npos) << file << ": " << outcome.message;
  }
  std::printf("model corpus: %d accepted, %d rejected\n", accepted, rejected);
  EXPECT_GT(accepted + rejected, 0);
}
