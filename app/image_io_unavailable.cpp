// image_io.h for builds without OpenImageIO (-DRETROAA_WITH_OPENIMAGEIO=OFF): every call says so.
#include <stdexcept>

#include "image_io.h"

namespace app {

namespace {
[[noreturn]] void unavailable(const std::string& path) {
  throw std::invalid_argument(path + ": this retroaa was built without OpenImageIO; it writes JSON and CSV only");
}
}  // namespace

void writeImage8(const std::string& path, int, int, const std::vector<uint8_t>&,
                 const std::map<std::string, std::string>&) {
  unavailable(path);
}
void writeImageFloat(const std::string& path, int, int, const std::vector<float>&,
                     const std::map<std::string, std::string>&) {
  unavailable(path);
}
std::vector<float> readImageRgb(const std::string& path, int&, int&) { unavailable(path); }

}  // namespace app
