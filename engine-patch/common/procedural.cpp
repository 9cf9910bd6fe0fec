#include "procedural.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace host {

namespace {

// The maps being painted, one value per texel; written out as RGBA8 at the end.
struct Canvas {
  int size;
  std::vector<glm::vec3> albedo;  // linear
  std::vector<float> height;      // in texels: slopes become the normal map
  std::vector<glm::vec2> specular;  // specular multiplier, gloss multiplier
  std::vector<glm::vec3> emissive;  // linear
  explicit Canvas(int n)
      : size(n),
        albedo(size_t(n) * n, glm::vec3(0.8f)),
        height(size_t(n) * n, 0.0f),
        specular(size_t(n) * n, glm::vec2(1.0f)),
        emissive(size_t(n) * n, glm::vec3(0.0f)) {}
  size_t at(int x, int y) const { return size_t((y + size) % size) * size + size_t((x + size) % size); }
  void fill(int x0, int y0, int w, int h, const std::function<void(size_t, int, int)>& paint) {
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) paint(at(x, y), x - x0, y - y0);
  }
};

uint8_t toSrgb8(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(s * 255.0f));
}
uint8_t toUnorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

SharedTextureImage image(const Canvas& c, const std::string& label,
                         const std::function<void(size_t, uint8_t*)>& texel) {
  auto out = std::make_shared<TextureImage>();
  out->width = out->height = c.size;
  out->label = label;
  out->rgba.resize(size_t(c.size) * c.size * 4);
  for (size_t t = 0; t < size_t(c.size) * c.size; ++t) texel(t, &out->rgba[t * 4]);
  return out;
}

// Splits a rectangle into panels on a 4-texel grid, down to between size/16 and size/4 on a side.
void splitPanels(int x, int y, int w, int h, int minSide, std::mt19937& rng,
                 std::vector<glm::ivec4>& panels) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const bool canSplitX = w >= 2 * minSide, canSplitY = h >= 2 * minSide;
  if ((!canSplitX && !canSplitY) || (w <= 4 * minSide && h <= 4 * minSide && unit(rng) < 0.3f)) {
    panels.push_back({x, y, w, h});
    return;
  }
  const bool alongX = canSplitX && (!canSplitY || w >= h);
  const int side = alongX ? w : h;
  int cut = minSide + int(unit(rng) * float(side - 2 * minSide));
  cut = std::max(minSide, cut / 4 * 4);
  if (alongX) {
    splitPanels(x, y, cut, h, minSide, rng, panels);
    splitPanels(x + cut, y, w - cut, h, minSide, rng, panels);
  } else {
    splitPanels(x, y, w, cut, minSide, rng, panels);
    splitPanels(x, y + cut, w, h - cut, minSide, rng, panels);
  }
}

void paintPanels(Canvas& c, const ProceduralPattern& p, std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const int n = c.size;
  std::vector<glm::ivec4> panels;
  splitPanels(0, 0, n, n, std::max(4, n / 16), rng, panels);
  for (const glm::ivec4& panel : panels) {
    const float shade = 0.65f + 0.35f * unit(rng);
    const glm::vec2 spec(0.4f + 0.6f * unit(rng), 0.6f + 0.4f * unit(rng));
    const float kind = unit(rng);
    c.fill(panel.x, panel.y, panel.z, panel.w, [&](size_t t, int u, int v) {
      c.albedo[t] = glm::vec3(shade);
      c.specular[t] = spec;
      // Hazard stripes (a tenth of the panels): diagonal, 4 texels apart — sub-pixel once minified.
      if (kind < 0.1f) c.albedo[t] = ((u + v) / 2) % 2 ? glm::vec3(0.75f, 0.55f, 0.05f) : glm::vec3(0.04f);
      // Lit windows: rows of 2×1-texel lights, every 4 texels, in `glow` of the panels.
      if (kind > 1.0f - p.glow && u % 4 == 1 && v % 6 == 2 && u + 2 < panel.z && v + 2 < panel.w)
        c.emissive[t] = glm::vec3(1.0f, 0.85f, 0.55f);
    });
    // Panel lines: one recessed dark texel along the panel's lower and left borders.
    c.fill(panel.x, panel.y, panel.z, 1, [&](size_t t, int, int) { c.albedo[t] *= 0.3f, c.height[t] = -1.5f; });
    c.fill(panel.x, panel.y, 1, panel.w, [&](size_t t, int, int) { c.albedo[t] *= 0.3f, c.height[t] = -1.5f; });
  }
  // Greebles: small raised blocks, 2 to 8 texels.
  const int greebles = n * n / 512;
  for (int g = 0; g < greebles; ++g) {
    const int w = 2 + int(unit(rng) * 7), h = 2 + int(unit(rng) * 7);
    const int x = int(unit(rng) * n), y = int(unit(rng) * n);
    const float shade = 0.5f + 0.5f * unit(rng);
    c.fill(x, y, w, h, [&](size_t t, int, int) { c.albedo[t] *= shade, c.height[t] = 1.0f; });
  }
  // Decals: a few discs and rings in red or white.
  const int decals = std::max(1, n / 128);
  for (int d = 0; d < decals; ++d) {
    const float radius = float(n) * (0.03f + 0.05f * unit(rng));
    const glm::vec2 centre(unit(rng) * n, unit(rng) * n);
    const glm::vec3 colour = unit(rng) < 0.5f ? glm::vec3(0.6f, 0.05f, 0.03f) : glm::vec3(0.9f);
    const bool ring = unit(rng) < 0.5f;
    const int r = int(std::ceil(radius));
    c.fill(int(centre.x) - r, int(centre.y) - r, 2 * r + 1, 2 * r + 1, [&](size_t t, int u, int v) {
      const float distance = glm::length(glm::vec2(u - r, v - r));
      if (distance <= radius && (!ring || distance >= 0.7f * radius)) c.albedo[t] = colour;
    });
  }
  // High-frequency normal detail: a hash per texel ("brushed" plating).
  for (size_t t = 0; t < c.height.size(); ++t) c.height[t] += 0.25f * (unit(rng) - 0.5f);
}

}  // namespace

MaterialMaps generateMaps(const ProceduralPattern& p) {
  const int n = p.texels;
  Canvas c(n);
  std::mt19937 rng(p.seed);
  if (p.pattern == "panels") {
    paintPanels(c, p, rng);
  } else if (p.pattern == "stripes") {
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const bool light = (x / 2) % 2 == 0;  // two texels light, two dark, along u
        c.albedo[c.at(x, y)] = glm::vec3(light ? 0.9f : 0.1f);
        c.height[c.at(x, y)] = light ? 0.5f : -0.5f;
      }
  } else if (p.pattern == "checker") {
    const int check = n / 8;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) c.albedo[c.at(x, y)] = glm::vec3((x / check + y / check) % 2 ? 0.9f : 0.05f);
  } else {
    throw TextureError("unknown procedural pattern '" + p.pattern + "' (allowed: panels, stripes, checker)");
  }

  const std::string label = "procedural " + p.pattern + " " + std::to_string(n) + " seed " + std::to_string(p.seed);
  MaterialMaps maps;
  maps.albedo = image(c, label + " albedo", [&](size_t t, uint8_t* out) {
    for (int k = 0; k < 3; ++k) out[k] = toSrgb8(c.albedo[t][k]);
    out[3] = 255;
  });
  maps.normal = image(c, label + " normal", [&](size_t t, uint8_t* out) {
    const int x = int(t % size_t(n)), y = int(t / size_t(n));
    // Central differences of the height (wrapping): the tangent-space normal of the relief.
    const float du = 0.5f * (c.height[c.at(x + 1, y)] - c.height[c.at(x - 1, y)]);
    const float dv = 0.5f * (c.height[c.at(x, y + 1)] - c.height[c.at(x, y - 1)]);
    const glm::vec3 normal = glm::normalize(glm::vec3(-du, -dv, 1.0f));
    for (int k = 0; k < 3; ++k) out[k] = toUnorm8(normal[k] * 0.5f + 0.5f);
    out[3] = 255;
  });
  maps.specular = image(c, label + " specular", [&](size_t t, uint8_t* out) {
    out[0] = out[1] = out[2] = toUnorm8(c.specular[t].x);
    out[3] = toUnorm8(c.specular[t].y);
  });
  if (p.glow > 0.0f)
    maps.emissive = image(c, label + " emissive", [&](size_t t, uint8_t* out) {
      for (int k = 0; k < 3; ++k) out[k] = toSrgb8(c.emissive[t][k]);
      out[3] = 255;
    });
  return maps;
}

}  // namespace host
