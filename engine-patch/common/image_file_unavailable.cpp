// A build without OpenImageIO (-DRETROAA_WITH_OPENIMAGEIO=OFF): procedural textures only.
#include "texture_image.h"

namespace host {

SharedTextureImage readTextureFile(const std::string& path) {
  throw TextureError(path + ": cannot read texture: retroaa was built without OpenImageIO");
}

SharedTextureImage decodeTextureBytes(const uint8_t*, size_t, const std::string&, const std::string& label) {
  throw TextureError(label + ": cannot decode embedded texture: retroaa was built without OpenImageIO");
}

}  // namespace host
