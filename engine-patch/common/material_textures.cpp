#include "material_textures.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace host {

namespace {
constexpr uint8_t kWhite[4] = {255, 255, 255, 255};
constexpr uint8_t kBlack[4] = {0, 0, 0, 255};
constexpr uint8_t kFlatNormal[4] = {128, 128, 255, 255};

int mipLevels(int width, int height) {
  return 1 + int(std::floor(std::log2(double(std::max(width, height)))));
}
}  // namespace

MaterialTextures::MaterialTextures(const std::vector<Material>& materials) {
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  sampler_ = Sampler(sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
  // Software rasterisers have the extension but filter anisotropically at a cost no frame budget
  // takes: llvmpipe rendered the textured demo (320x240, `off`) in 968 ms with 16x against 64 ms with
  // trilinear. There the textures stay trilinear.
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software = renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"));
  if (!software && (epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
                    epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))) {
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &maxAnisotropy_);
    maxAnisotropy_ = std::clamp(maxAnisotropy_, 1.0f, 16.0f);
    glSamplerParameterf(sampler, GL_TEXTURE_MAX_ANISOTROPY_EXT, maxAnisotropy_);
  }
  // One neutral texture per role serves every material without that map.
  const GLuint neutralColour = upload(nullptr, true, kWhite);
  const GLuint neutralNormal = upload(nullptr, false, kFlatNormal);
  const GLuint neutralSpecular = upload(nullptr, false, kWhite);
  const GLuint noEmission = upload(nullptr, true, kBlack);
  neutral_ = {neutralColour, neutralNormal, neutralSpecular, neutralColour, false, neutralColour};
  for (const Material& material : materials) {
    const MaterialMaps& m = material.maps;
    maps_.push_back({m.albedo ? upload(m.albedo, true, kWhite) : neutralColour,
                     m.normal ? upload(m.normal, false, kFlatNormal) : neutralNormal,
                     m.specular ? upload(m.specular, false, kWhite) : neutralSpecular,
                     m.emissive ? upload(m.emissive, true, kWhite) : neutralColour, bool(m.normal),
                     m.emissive ? noEmission : neutralColour});
  }
}

GLuint MaterialTextures::upload(const SharedTextureImage& image, bool srgb, const uint8_t neutral[4]) {
  const int width = image ? image->width : 1, height = image ? image->height : 1;
  const uint8_t* texels = image ? image->rgba.data() : neutral;
  GLuint name = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &name);
  textures_.emplace_back(name);
  glTextureStorage2D(name, mipLevels(width, height), srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Row 0 of the image at t = 0: texture coordinates run top-down, as glTF's do.
  glTextureSubImage2D(name, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glGenerateTextureMipmap(name);
  const std::string label = image ? "host.material." + image->label : "host.material.neutral";
  glObjectLabel(GL_TEXTURE, name, GLsizei(std::min<size_t>(label.size(), 200)), label.c_str());
  return name;
}

void MaterialTextures::bind(size_t material) const {
  const Maps& m = mapsOn_ ? maps_[material] : neutral_;
  const GLuint textures[4] = {m.albedo, m.normal, m.specular,
                              mapsOn_ ? m.emissive : maps_[material].emissiveWhileMapsOff};
  glBindTextures(kFirstUnit, 4, textures);
  const GLuint samplers[4] = {sampler_, sampler_, sampler_, sampler_};
  glBindSamplers(kFirstUnit, 4, samplers);
}

void MaterialTextures::unbind() const {
  glBindSamplers(kFirstUnit, 4, nullptr);
}

void MaterialTextures::setLodBias(float bias) { glSamplerParameterf(sampler_, GL_TEXTURE_LOD_BIAS, bias); }

}  // namespace host
