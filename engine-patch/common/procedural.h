// Procedural material maps for generated models: texture detail at several scales, deterministic for
// a seed, with no image file. Written by hand: no Debian package generates such content.
#pragma once

#include "texture_image.h"

#include <cstdint>
#include <string>

namespace host {

struct ProceduralPattern {
  // "panels": hull plating — panel lines, raised greebles, hazard stripes, decals, a high-frequency
  //           normal map, and with `glow` > 0 lit windows in the emissive map;
  // "stripes": fine stripes two texels apart across the whole map, in albedo and normal (moiré);
  // "checker": an 8×8 checkerboard, flat (the ground truth's texture-filtering test).
  std::string pattern = "panels";
  int texels = 256;  // a power of two, 16 … 2048 on a side
  uint32_t seed = 1;
  float glow = 0.0f;  // fraction of panels that carry lit windows ("panels")
};

// Albedo, normal and specular maps (and emissive with glow), `uvScale` left at 1.
MaterialMaps generateMaps(const ProceduralPattern& pattern);

}  // namespace host
