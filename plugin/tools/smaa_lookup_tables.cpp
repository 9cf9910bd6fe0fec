// Generates SMAA's two lookup textures at build time, from the definitions of Jimenez et al.,
// "SMAA: Enhanced Subpixel Morphological Antialiasing" (Eurographics 2012), and of its authors'
// AreaTex/SearchTex scripts (iryoku/smaa, read for the definitions; this code is ours). Usage:
//   smaa_lookup_tables <output.inc>
// writes C++ arrays the plugin includes (methods/smaa.cpp) and the table tests check.
//
// Area texture (RG8, 160 × 560): for a line between two crossing-edge patterns, the fraction of the
// current pixel that the revectorised silhouette covers on each side of the edge (r: the side the
// neighbour colour comes from above/left of the edge, g: below/right). Seven 80-texel-high rows of
// subsample offsets; in each, the orthogonal block (x 0..79) holds 16 patterns of 16 × 16 distances
// (quadratically compressed: texel (l, r) is the distance pair (l², r²)) in a 5 × 5 grid indexed by
// round(4·e) of the bilinear crossing-edge fetches, and the diagonal block (x 80..159, first five
// rows) 16 patterns of 20 × 20 distances in a 4 × 4 grid.
//
// Search texture (R8UI, 66 × 33): how many pixels the last step of a horizontal/vertical search
// overshot (0, 1 or 2), indexed by the bilinear fetch of four edges (value · 32) at that step; the left
// half serves searches towards −x (or −y), the right half towards +x (+y).
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr int kOrthoSize = 16, kDiagSize = 20, kSlot = 80;
constexpr int kAreaWidth = 2 * kSlot, kAreaHeight = 7 * kSlot;
constexpr int kSearchWidth = 66, kSearchHeight = 33;
constexpr int kDiagSamples = 30;           // brute-force samples per axis for a diagonal area
constexpr double kSmoothMaxDistance = 32;  // U patterns shorter than this are rounded off

// Subsample offsets of the rows (SMAA's subsample indices select them): 0 for SMAA 1x, ±0.25 for S2x's
// two samples, ±0.125/±0.375 for the first two samples of other patterns.
constexpr std::array<double, 7> kOrthoOffsets = {0.0, -0.25, 0.25, -0.125, 0.125, -0.375, 0.375};
constexpr std::array<std::array<double, 2>, 5> kDiagOffsets = {
    {{0.0, 0.0}, {0.25, -0.25}, {-0.25, 0.25}, {0.125, -0.125}, {-0.125, 0.125}}};

// Where each pattern's block sits in its 5 × 5 (orthogonal) or 4 × 4 (diagonal) grid: the crossing
// edges e1, e2 of a pattern read back as round(4·e) ∈ {0, 1, 3, 4} (orthogonal) or 2·c.x + c.y (diagonal).
constexpr int kOrthoGrid[16][2] = {{0, 0}, {3, 0}, {0, 3}, {3, 3}, {1, 0}, {4, 0}, {1, 3}, {4, 3},
                                   {0, 1}, {3, 1}, {0, 4}, {3, 4}, {1, 1}, {4, 1}, {1, 4}, {4, 4}};
constexpr int kDiagGrid[16][2] = {{0, 0}, {1, 0}, {0, 2}, {1, 2}, {2, 0}, {3, 0}, {2, 2}, {3, 2},
                                  {0, 1}, {1, 1}, {0, 3}, {1, 3}, {2, 1}, {3, 1}, {2, 3}, {3, 3}};

struct Vec2 {
  double x = 0, y = 0;
};
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }

// The areas (one on each side of the edge) that the line p1 → p2 cuts from the pixel spanning
// x .. x+1 of an edge that lies along y = 0.
Vec2 areaUnderLine(Vec2 p1, Vec2 p2, double x) {
  const Vec2 d{p2.x - p1.x, p2.y - p1.y};
  const double x1 = x, x2 = x + 1.0;
  const double y1 = p1.y + d.y * (x1 - p1.x) / d.x;
  const double y2 = p1.y + d.y * (x2 - p1.x) / d.x;
  const bool inside = (x1 >= p1.x && x1 < p2.x) || (x2 > p1.x && x2 <= p2.x);
  if (!inside) return {0, 0};
  const bool trapezoid = std::copysign(1.0, y1) == std::copysign(1.0, y2) || std::abs(y1) < 1e-4 || std::abs(y2) < 1e-4;
  if (trapezoid) {
    const double a = (y1 + y2) / 2;
    return a < 0 ? Vec2{std::abs(a), 0} : Vec2{0, std::abs(a)};
  }
  // The line crosses the edge inside the pixel: two triangles, one on each side.
  const double crossing = -p1.y * d.x / d.y + p1.x;
  const double fraction = crossing - std::floor(crossing);
  const double a1 = crossing > p1.x ? y1 * fraction / 2 : 0.0;
  const double a2 = crossing < p2.x ? y2 * (1.0 - fraction) / 2 : 0.0;
  const double dominant = std::abs(a1) > std::abs(a2) ? a1 : -a2;
  return dominant < 0 ? Vec2{std::abs(a1), std::abs(a2)} : Vec2{std::abs(a2), std::abs(a1)};
}

// Short U shapes are rounded (the square-root curve) rather than cut as two straight halves.
std::array<Vec2, 2> smoothU(double d, Vec2 a1, Vec2 a2) {
  auto rounded = [](Vec2 a) { return Vec2{std::sqrt(a.x * 2) * 0.5, std::sqrt(a.y * 2) * 0.5}; };
  const double p = std::min(std::max(d / kSmoothMaxDistance, 0.0), 1.0);
  auto lerp = [p](Vec2 a, Vec2 b) { return Vec2{a.x + (b.x - a.x) * p, a.y + (b.y - a.y) * p}; };
  return {lerp(rounded(a1), a1), lerp(rounded(a2), a2)};
}

// An orthogonal pattern: crossing edges at both ends of a line `left` pixels to the left and `right`
// to the right of the current one. Bits: 1 crossing edge below at the left end, 2 below at the
// right end, 4 above at the left end, 8 above at the right end.
Vec2 orthoArea(int pattern, double left, double right, double offset) {
  const double d = left + right + 1;
  const double above = 0.5 + offset, below = 0.5 + offset - 1.0;
  const Vec2 middle{d / 2, 0};
  auto area = [&](Vec2 p1, Vec2 p2) { return areaUnderLine(p1, p2, left); };
  auto halfBlend = [&](double y1, double y2) {  // Z shapes: full revectorisation mixed with two L's
    const Vec2 full = area({0, y1}, {d, y2});
    if (std::abs(offset) == 0) return full;
    const Vec2 halves = area({0, y1}, middle) + area(middle, {d, y2});
    return (full + halves) * 0.5;
  };
  switch (pattern) {
    case 0: return {0, 0};                                             // ──────
    case 1: return left <= right ? area({0, below}, middle) : Vec2{};  // L pointing down at the left
    case 2: return left >= right ? area(middle, {d, below}) : Vec2{};
    case 3: {  // U opening down
      auto s = smoothU(d, area({0, below}, middle), area(middle, {d, below}));
      return s[0] + s[1];
    }
    case 4: return left <= right ? area({0, above}, middle) : Vec2{};
    case 5: return {0, 0};  // crossing both ways at the left: no slope to reconstruct
    case 6: return halfBlend(above, below);
    case 7: return area({0, above}, {d, below});
    case 8: return left >= right ? area(middle, {d, above}) : Vec2{};
    case 9: return halfBlend(below, above);
    case 10: return {0, 0};
    case 11: return area({0, below}, {d, above});
    case 12: {  // U opening up
      auto s = smoothU(d, area({0, above}, middle), area(middle, {d, above}));
      return s[0] + s[1];
    }
    case 13: return area({0, below}, {d, above});
    case 14: return area({0, above}, {d, below});
    default: return {0, 0};  // 15: crossing both ways at both ends
  }
}

// The fraction of the unit square at `corner` on the positive side of the line p1 → p2, by brute
// force sampling (the diagonal patterns' definition).
double coveredFraction(Vec2 p1, Vec2 p2, Vec2 corner) {
  if (p1.x == p2.x && p1.y == p2.y) return 1.0;
  const Vec2 mid{(p1.x + p2.x) / 2, (p1.y + p2.y) / 2};
  const double a = p2.y - p1.y, b = p1.x - p2.x;
  int inside = 0;
  for (int i = 0; i < kDiagSamples; ++i)
    for (int j = 0; j < kDiagSamples; ++j) {
      const double x = corner.x + double(i) / (kDiagSamples - 1), y = corner.y + double(j) / (kDiagSamples - 1);
      inside += a * (x - mid.x) + b * (y - mid.y) > 0;
    }
  return double(inside) / (kDiagSamples * kDiagSamples);
}

// A diagonal pattern: the ends of a 45° line are unknown (L or U, and what lies beyond), so most
// patterns blend the two possibilities.
Vec2 diagArea(int pattern, double left, double right, std::array<double, 2> offset) {
  const double d = left + right + 1;
  auto area = [&](Vec2 p1, Vec2 p2) {
    if (kDiagGrid[pattern][0] > 0) p1 = p1 + Vec2{offset[0], offset[1]};
    if (kDiagGrid[pattern][1] > 0) p2 = p2 + Vec2{offset[0], offset[1]};
    const double a1 = coveredFraction(p1, p2, Vec2{1, 0} + Vec2{left, left});
    const double a2 = coveredFraction(p1, p2, Vec2{1, 1} + Vec2{left, left});
    return Vec2{1.0 - a1, a2};
  };
  const Vec2 span{d, d};
  const Vec2 o00{0, 0}, o10{1, 0}, o11{1, 1};
  auto blend = [&](Vec2 a, Vec2 b, Vec2 c, Vec2 e) { return (area(a, b + span) + area(c, e + span)) * 0.5; };
  switch (pattern) {
    case 0: return blend(o11, o11, o10, o10);
    case 1: return blend(o10, o00, o10, o10);
    case 2: return blend(o00, o10, o10, o10);
    case 3: return area(o10, o10 + span);
    case 4: return blend(o11, o00, o11, o10);
    case 5: return blend(o11, o00, o10, o10);
    case 6: return area(o11, o10 + span);
    case 7: return blend(o11, o10, o10, o10);
    case 8: return blend(o00, o11, o10, o11);
    case 9: return area(o10, o11 + span);
    case 10: return blend(o00, o11, o10, o10);
    case 11: return blend(o10, o11, o10, o10);
    case 12: return area(o11, o11 + span);
    case 13: return blend(o11, o11, o10, o11);
    case 14: return blend(o11, o11, o11, o10);
    default: return blend(o11, o11, o10, o10);  // 15
  }
}

unsigned char toByte(double v) { return (unsigned char)std::lround(std::min(std::max(v, 0.0), 1.0) * 255.0); }

std::vector<unsigned char> areaTexture() {
  std::vector<unsigned char> rg(size_t(kAreaWidth) * kAreaHeight * 2, 0);
  auto put = [&](int x, int y, Vec2 v) {
    rg[(size_t(y) * kAreaWidth + x) * 2 + 0] = toByte(v.x);
    rg[(size_t(y) * kAreaWidth + x) * 2 + 1] = toByte(v.y);
  };
  for (size_t row = 0; row < kOrthoOffsets.size(); ++row)
    for (int pattern = 0; pattern < 16; ++pattern)
      for (int l = 0; l < kOrthoSize; ++l)
        for (int r = 0; r < kOrthoSize; ++r)
          put(l + kOrthoSize * kOrthoGrid[pattern][0], int(row) * kSlot + r + kOrthoSize * kOrthoGrid[pattern][1],
              orthoArea(pattern, double(l * l), double(r * r), kOrthoOffsets[row]));
  for (size_t row = 0; row < kDiagOffsets.size(); ++row)
    for (int pattern = 0; pattern < 16; ++pattern)
      for (int l = 0; l < kDiagSize; ++l)
        for (int r = 0; r < kDiagSize; ++r)
          put(kSlot + l + kDiagSize * kDiagGrid[pattern][0], int(row) * kSlot + r + kDiagSize * kDiagGrid[pattern][1],
              diagArea(pattern, l, r, kDiagOffsets[row]));
  return rg;
}

// The four edges a search's bilinear fetch mixes: e[0], e[1] the row beyond (weights 1/8 · 1/4, 3/4),
// e[2], e[3] the current row (7/8 · 1/4, 3/4); e[3] is the pixel the step landed on.
int bilinearCode(const std::array<int, 4>& e) { return e[0] + 3 * e[1] + 7 * e[2] + 21 * e[3]; }

std::vector<unsigned char> searchTexture() {
  std::array<std::array<int, 4>, 33> edgesOfCode{};
  std::array<bool, 33> valid{};
  for (int bits = 0; bits < 16; ++bits) {
    std::array<int, 4> e = {(bits >> 3) & 1, (bits >> 2) & 1, (bits >> 1) & 1, bits & 1};
    edgesOfCode[bilinearCode(e)] = e;
    valid[bilinearCode(e)] = true;
  }
  // `along`: the edges of the line being followed; `crossing`: edges across it.
  auto deltaTowardsStart = [](const std::array<int, 4>& crossing, const std::array<int, 4>& along) {
    int d = along[3] == 1 ? 1 : 0;
    if (d == 1 && along[2] == 1 && crossing[1] != 1 && crossing[3] != 1) ++d;
    return d;
  };
  auto deltaTowardsEnd = [](const std::array<int, 4>& crossing, const std::array<int, 4>& along) {
    int d = (along[3] == 1 && crossing[1] != 1 && crossing[3] != 1) ? 1 : 0;
    if (d == 1 && along[2] == 1 && crossing[0] != 1 && crossing[2] != 1) ++d;
    return d;
  };
  std::vector<unsigned char> texels(size_t(kSearchWidth) * kSearchHeight, 0);
  for (int x = 0; x < 33; ++x)
    for (int y = 0; y < 33; ++y) {
      if (!valid[x] || !valid[y]) continue;
      texels[size_t(y) * kSearchWidth + x] = (unsigned char)deltaTowardsStart(edgesOfCode[x], edgesOfCode[y]);
      texels[size_t(y) * kSearchWidth + 33 + x] = (unsigned char)deltaTowardsEnd(edgesOfCode[x], edgesOfCode[y]);
    }
  return texels;
}

void writeArray(FILE* out, const char* name, const std::vector<unsigned char>& bytes) {
  std::fprintf(out, "constexpr unsigned char %s[%zu] = {", name, bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) std::fprintf(out, "%s%u,", i % 24 == 0 ? "\n  " : "", bytes[i]);
  std::fprintf(out, "\n};\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: smaa_lookup_tables <output.inc>\n");
    return 2;
  }
  FILE* out = std::fopen(argv[1], "w");
  if (!out) {
    std::perror(argv[1]);
    return 1;
  }
  std::fprintf(out, "// Generated by plugin/tools/smaa_lookup_tables.cpp at build time; do not edit.\n");
  std::fprintf(out, "constexpr int kSmaaAreaWidth = %d, kSmaaAreaHeight = %d;\n", kAreaWidth, kAreaHeight);
  std::fprintf(out, "constexpr int kSmaaSearchWidth = %d, kSmaaSearchHeight = %d;\n", kSearchWidth, kSearchHeight);
  writeArray(out, "kSmaaAreaTexture", areaTexture());
  writeArray(out, "kSmaaSearchTexture", searchTexture());
  return std::fclose(out) == 0 ? 0 : 1;
}
