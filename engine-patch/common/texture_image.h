// Material textures on the CPU: RGBA8 images, read from files through OpenImageIO (external or embedded
// in a model) or generated (procedural.h). The renderers upload them mipmapped (material_textures.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace host {

struct TextureImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // top-down rows, 4 bytes per texel
  std::string label;          // file or generator, for GL labels and messages
};
using SharedTextureImage = std::shared_ptr<const TextureImage>;

// What a material's maps hold. Albedo and emissive are sRGB-encoded colours; normal is a tangent-space
// unit vector in rgb (x right along u, y along v, z out); specular is a specular-colour multiplier in
// rgb and a gloss multiplier in alpha.
struct MaterialMaps {
  SharedTextureImage albedo, normal, specular, emissive;
  float uvScale = 1.0f;  // texture repeats per unit of the mesh's texture coordinates
  bool any() const { return albedo || normal || specular || emissive; }
};

class TextureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Images larger than this on a side are refused before their texels are read, and a scene's textures
// together (files, embedded and generated) may hold at most kMaxSceneTextureBytes: memory stays bounded
// whatever file a scene names.
constexpr int kMaxTextureSide = 8192;
constexpr size_t kMaxSceneTextureBytes = size_t(512) << 20;

// Reads an image file (any format OpenImageIO reads) as RGBA8: grey and RGB gain opaque alpha, wider
// types are converted. Throws TextureError naming the file; so does a build without OpenImageIO.
SharedTextureImage readTextureFile(const std::string& path);
// The same for an image held in memory (a model's embedded texture); `formatHint` is the file
// extension its format uses ("png", "jpg"), `label` names it in errors.
SharedTextureImage decodeTextureBytes(const uint8_t* data, size_t size, const std::string& formatHint,
                                      const std::string& label);

}  // namespace host
