#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "texture_image.h"

#include <algorithm>
#include <filesystem>

namespace host {

namespace {

SharedTextureImage readRgba8(OIIO::ImageInput& input, const std::string& label) {
  const OIIO::ImageSpec& spec = input.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxTextureSide || spec.height > kMaxTextureSide)
    throw TextureError(label + ": image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                       " texels; textures must be 1 to " + std::to_string(kMaxTextureSide) + " on a side");
  if (spec.nchannels < 1) throw TextureError(label + ": image has no channels");
  auto image = std::make_shared<TextureImage>();
  image->width = spec.width;
  image->height = spec.height;
  image->label = label;
  const int channels = std::min(spec.nchannels, 4);
  std::vector<uint8_t> texels(size_t(spec.width) * spec.height * channels);
  if (!input.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, texels.data()))
    throw TextureError(label + ": cannot read image: " + input.geterror());
  image->rgba.resize(size_t(spec.width) * spec.height * 4);
  for (size_t t = 0; t < size_t(spec.width) * spec.height; ++t) {
    const uint8_t* in = &texels[t * channels];
    uint8_t* out = &image->rgba[t * 4];
    if (channels <= 2) {  // grey, grey + alpha
      out[0] = out[1] = out[2] = in[0];
      out[3] = channels == 2 ? in[1] : 255;
    } else {
      out[0] = in[0], out[1] = in[1], out[2] = in[2];
      out[3] = channels == 4 ? in[3] : 255;
    }
  }
  return image;
}

}  // namespace

SharedTextureImage readTextureFile(const std::string& path) {
  // Only regular files of bounded size: /dev/zero or a FIFO would never end.
  constexpr std::uintmax_t kMaxTextureFileBytes = 256u << 20;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw TextureError(path + ": texture does not exist");
  if (!std::filesystem::is_regular_file(path, error)) throw TextureError(path + ": texture is not a regular file");
  if (std::filesystem::file_size(path, error) > kMaxTextureFileBytes)
    throw TextureError(path + ": texture file is larger than 256 MiB");
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw TextureError(path + ": cannot read texture: " + OIIO::geterror());
  return readRgba8(*input, path);
}

SharedTextureImage decodeTextureBytes(const uint8_t* data, size_t size, const std::string& formatHint,
                                      const std::string& label) {
  OIIO::Filesystem::IOMemReader memory(const_cast<uint8_t*>(data), size);
  // The name only picks the format reader; the texels come from `memory`.
  auto input =
      OIIO::ImageInput::open("embedded." + (formatHint.empty() ? std::string("png") : formatHint), nullptr, &memory);
  if (!input) throw TextureError(label + ": cannot decode embedded texture: " + OIIO::geterror());
  return readRgba8(*input, label);
}

}  // namespace host
