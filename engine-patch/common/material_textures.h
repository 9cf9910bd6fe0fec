// The scene's material maps on the GPU, shared by both hosts' model passes: one mipmapped texture per
// map (sRGB for albedo and emissive), 1×1 neutral textures where a material has none, and one sampler
// with trilinear filtering, anisotropic (16x) where the context has it and is no software rasteriser,
// and a LOD bias the ground truth sets.
#pragma once

#include "gl_objects.h"
#include "scene.h"

#include <vector>

namespace host {

class MaterialTextures {
 public:
  // Texture units the model shaders read: albedo, normal, specular, emissive.
  static constexpr GLuint kFirstUnit = 0;
  explicit MaterialTextures(const std::vector<Material>& materials);
  // The four maps and the sampler on units kFirstUnit … +3; the neutral ones while maps are off.
  void bind(size_t material) const;
  bool normalMapped(size_t material) const { return mapsOn_ && maps_[material].normalMapped; }
  void unbind() const;  // the sampler off those units again: the host's own passes sample them unfiltered
  // A ground truth at s×s samples per pixel sets −log2 s, so every supersample filters its own
  // footprint as an s× larger render would.
  void setLodBias(float bias);
  float maxAnisotropy() const { return maxAnisotropy_; }  // 1: the context has no anisotropic filtering
  // Off: every material renders as before it had maps — its constants alone, and no emission where a
  // glow map made it (the ground truth's edge mask, which must find geometry and lighting edges, not
  // texture detail).
  void setMapsOn(bool on) { mapsOn_ = on; }

 private:
  struct Maps {
    GLuint albedo, normal, specular, emissive;  // names in textures_
    bool normalMapped;
    GLuint emissiveWhileMapsOff;  // white (the constant alone), or black where a glow map sets the emission
  };
  GLuint upload(const SharedTextureImage& image, bool srgb, const uint8_t neutral[4]);
  std::vector<Texture> textures_;
  std::vector<Maps> maps_;
  Sampler sampler_;
  float maxAnisotropy_ = 1.0f;
  bool mapsOn_ = true;
  Maps neutral_{};
};

}  // namespace host
