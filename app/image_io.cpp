#include "image_io.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace app {

namespace {
void write(const std::string& path, const OIIO::ImageSpec& spec, const void* pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write image: " + OIIO::geterror());
  if (!out->open(path, spec) || !out->write_image(spec.format, pixels))
    throw std::runtime_error(path + ": cannot write image: " + out->geterror());
  out->close();
}
}  // namespace

void writeImage8(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
                 const std::map<std::string, std::string>& metadata) {
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  write(path, spec, rgba.data());
}

void writeImageFloat(const std::string& path, int width, int height, const std::vector<float>& rgba,
                     const std::map<std::string, std::string>& metadata) {
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
  spec.set_format(OIIO::TypeDesc::HALF);
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write image: " + OIIO::geterror());
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgba.data()))
    throw std::runtime_error(path + ": cannot write image: " + out->geterror());
  out->close();
}

std::vector<float> readImageRgb(const std::string& path, int& width, int& height) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  std::vector<float> all(size_t(width) * height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
    throw std::runtime_error(path + ": cannot read image: " + in->geterror());
  std::vector<float> rgb(size_t(width) * height * 3);
  for (size_t p = 0; p < size_t(width) * height; ++p)
    for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
  return rgb;
}

}  // namespace app
