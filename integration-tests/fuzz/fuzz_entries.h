// The parsers a user can feed, as fuzzing entry points. Each returns normally for valid input and
// for input it rejects with its documented error (SceneError, ModelLoadError, an InvalidConfig
// status); a crash, a hang, a sanitizer report or any other exception is a bug. The libFuzzer targets
// (make fuzz) and the corpus replay in make test call the same functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fuzz {

// The result of one input, for the replay test to check what the message names.
struct Outcome {
  bool accepted = false;
  std::string message;  // the error, when rejected
};

Outcome sceneText(const uint8_t* data, size_t size);   // host::parseScene, camera paths inline
Outcome configText(const uint8_t* data, size_t size);  // config files, settings lists, FSO flags
Outcome modelFile(const uint8_t* data, size_t size);   // glTF/OBJ/... through host::loadModel

}  // namespace fuzz
