#include "fuzz_entries.h"

#include "mesh.h"
#include "retroaa/config.h"
#include "scene.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fuzz {

Outcome sceneText(const uint8_t* data, size_t size) {
  try {
    host::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                     std::filesystem::temp_directory_path().string());
    return {true, ""};
  } catch (const host::SceneError& e) {
    return {false, e.what()};
  }
}

Outcome configText(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  retroaa::Config config;
  const retroaa::Status file = retroaa::applyConfigText(config, text, "fuzz.cfg");
  retroaa::Config other;
  const retroaa::Status list = retroaa::applySettingsList(other, text, "RETROAA_SETTINGS");
  // The first line as an FSO flag and its value ("-msaa 4").
  const std::string line = text.substr(0, text.find('\n'));
  const size_t space = line.find(' ');
  std::vector<std::string> warnings;
  retroaa::Config fso;
  retroaa::applyFsoFlag(fso, line.substr(0, space), space == std::string::npos ? "" : line.substr(space + 1), warnings);
  // What was accepted must survive a round trip through its own text.
  if (file) {
    retroaa::Config reread;
    if (!retroaa::applyConfigText(reread, retroaa::toConfigText(config), "roundtrip") ||
        retroaa::toConfigText(reread) != retroaa::toConfigText(config))
      __builtin_trap();
  }
  return {bool(file), file ? "" : file.error().message};
}

Outcome modelFile(const uint8_t* data, size_t size) {
  // assimp picks the importer by extension and content: try the formats scenes use.
  static const std::string base = (std::filesystem::temp_directory_path() / ("retroaa_fuzz_model_" + std::to_string(getpid()))).string();
  Outcome last;
  for (const char* extension : {".obj", ".gltf", ".glb"}) {
    const std::string path = base + extension;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    try {
      host::loadModel(path);
      last = {true, ""};
    } catch (const host::ModelLoadError& e) {
      last = {false, e.what()};
    }
    std::filesystem::remove(path);
  }
  return last;
}

}  // namespace fuzz
