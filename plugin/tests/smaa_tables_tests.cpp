// The SMAA lookup textures our generator wrote at build time (plugin/tools/smaa_lookup_tables.cpp):
// properties that follow from their definitions, and a few values worked out by hand.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace {

#include "smaa_lookup_tables.inc"

constexpr int kOrthoSize = 16, kDiagSize = 20, kSlot = 80;
// Where the generator places each orthogonal and diagonal pattern's block.
constexpr int kOrthoGrid[16][2] = {{0, 0}, {3, 0}, {0, 3}, {3, 3}, {1, 0}, {4, 0}, {1, 3}, {4, 3},
                                   {0, 1}, {3, 1}, {0, 4}, {3, 4}, {1, 1}, {4, 1}, {1, 4}, {4, 4}};
constexpr int kDiagGrid[16][2] = {{0, 0}, {1, 0}, {0, 2}, {1, 2}, {2, 0}, {3, 0}, {2, 2}, {3, 2},
                                  {0, 1}, {1, 1}, {0, 3}, {1, 3}, {2, 1}, {3, 1}, {2, 3}, {3, 3}};

// (r, g) of orthogonal `pattern` at texel distances (l, r), i.e. l² and r² pixels, in offset `row`.
std::array<int, 2> ortho(int pattern, int l, int r, int row = 0) {
  const int x = l + kOrthoSize * kOrthoGrid[pattern][0], y = row * kSlot + r + kOrthoSize * kOrthoGrid[pattern][1];
  const size_t i = (size_t(y) * kSmaaAreaWidth + x) * 2;
  return {kSmaaAreaTexture[i], kSmaaAreaTexture[i + 1]};
}
std::array<int, 2> diag(int pattern, int l, int r, int row = 0) {
  const int x = kSlot + l + kDiagSize * kDiagGrid[pattern][0], y = row * kSlot + r + kDiagSize * kDiagGrid[pattern][1];
  const size_t i = (size_t(y) * kSmaaAreaWidth + x) * 2;
  return {kSmaaAreaTexture[i], kSmaaAreaTexture[i + 1]};
}
int search(int x, int y) { return kSmaaSearchTexture[size_t(y) * kSmaaSearchWidth + x]; }

// The search fetch's bilinear code of four edges (e0, e1 the far row; e3 the landed-on pixel).
int code(int e0, int e1, int e2, int e3) { return e0 + 3 * e1 + 7 * e2 + 21 * e3; }

}  // namespace

TEST(SmaaTables, HaveThePapersLayout) {
  EXPECT_EQ(kSmaaAreaWidth, 160);
  EXPECT_EQ(kSmaaAreaHeight, 560);  // 7 subsample-offset rows of 80
  EXPECT_EQ(kSmaaSearchWidth, 66);
  EXPECT_EQ(kSmaaSearchHeight, 33);
}

TEST(SmaaTables, LinesWithoutASlopeGetNoArea) {
  // No crossing edge (0), or crossing edges on both sides at an end (5, 10, 15): nothing to revectorise.
  for (int row = 0; row < 7; ++row)
    for (int pattern : {0, 5, 10, 15})
      for (int l = 0; l < kOrthoSize; ++l)
        for (int r = 0; r < kOrthoSize; ++r)
          EXPECT_EQ(ortho(pattern, l, r, row), (std::array<int, 2>{0, 0})) << pattern << " " << l << "," << r;
}

TEST(SmaaTables, ZeroDistanceValuesWorkedOutByHand) {
  // Pattern 1 (an L going down at the left end) on a one-pixel line: the line from (0, −½) to (½, 0)
  // crosses the edge at x = ½, leaving a triangle of ½ · ½ · ½ = ⅛ below: 0.125 · 255 → 32.
  EXPECT_EQ(ortho(1, 0, 0), (std::array<int, 2>{32, 0}));
  // Its vertical mirror (pattern 4, going up) has the same area on the other side of the edge.
  EXPECT_EQ(ortho(4, 0, 0), (std::array<int, 2>{0, 32}));
  // A U of one pixel (pattern 3) is two such triangles of ⅛, each rounded off (short U shapes) towards
  // √(2·⅛)/2 = ¼ by 1 − d/32: 2 · (¼ − (¼ − ⅛)/32) = 0.4922 → 126.
  EXPECT_EQ(ortho(3, 0, 0), (std::array<int, 2>{126, 0}));
}

TEST(SmaaTables, MirroredPatternsHaveMirroredAreas) {
  for (int l = 0; l < kOrthoSize; ++l)
    for (int r = 0; r < kOrthoSize; ++r) {
      // Left-right mirrors swap the distances.
      EXPECT_EQ(ortho(1, l, r), ortho(2, r, l)) << l << "," << r;
      EXPECT_EQ(ortho(4, l, r), ortho(8, r, l)) << l << "," << r;
      EXPECT_EQ(ortho(6, l, r), ortho(9, r, l)) << l << "," << r;
      EXPECT_EQ(ortho(3, l, r), ortho(3, r, l)) << l << "," << r;
      // Up-down mirrors swap the sides of the edge.
      const auto down = ortho(1, l, r), up = ortho(4, l, r);
      EXPECT_EQ(down[0], up[1]) << l << "," << r;
      EXPECT_EQ(down[1], up[0]) << l << "," << r;
    }
}

TEST(SmaaTables, AreaFallsAwayFromTheCornerAlongAnEdge) {
  // Along an L's edge the revectorised line approaches the edge linearly: further from the corner
  // (larger left distance, the right one fixed), less area; a longer line puts the corner pixel's
  // area closer to a half.
  for (int r = 0; r < kOrthoSize; ++r)
    for (int l = 1; l * l <= r * r; ++l) EXPECT_LE(ortho(1, l, r)[0], ortho(1, l - 1, r)[0]) << l << "," << r;
  for (int r = 1; r < kOrthoSize; ++r) EXPECT_GE(ortho(1, 0, r)[0], ortho(1, 0, r - 1)[0]) << r;
  EXPECT_LE(ortho(1, 0, kOrthoSize - 1)[0], 128);
}

TEST(SmaaTables, SubsampleOffsetsMoveTheArea) {
  // A Z pattern's line passes through the edge's middle at offset 0; a sample offset shifts where it
  // crosses, so rows −¼ and +¼ differ from row 0 and from each other.
  EXPECT_NE(ortho(6, 2, 2, 1), ortho(6, 2, 2, 0));
  EXPECT_NE(ortho(6, 2, 2, 1), ortho(6, 2, 2, 2));
}

TEST(SmaaTables, TheNullDiagonalPatternIsFilteredUnlikeTheOrthogonalOne) {
  // A 45° line with no known ends still needs blending (the ends are unknown, so both possibilities
  // are averaged): its area is not zero, and it is the same at both ends of a symmetric line.
  EXPECT_GT(diag(0, 3, 3)[0] + diag(0, 3, 3)[1], 0);
  for (int l = 0; l < kDiagSize; ++l)
    for (int r = 0; r < kDiagSize; ++r)
      for (int c : diag(0, l, r)) EXPECT_LE(c, 255);
}

TEST(SmaaTables, SearchTextureCountsTheLastStepsOvershoot) {
  // Entries that no four-edge combination produces stay 0.
  EXPECT_EQ(search(1, 2), 0);
  // No edges along the line: the step overshot by 0 in the table's terms (the shader's 3.25 bias
  // accounts for the two pixels of the step), whatever crosses.
  for (int crossing = 0; crossing < 33; ++crossing) EXPECT_EQ(search(crossing, code(0, 0, 0, 0)), 0);
  // Both pixels of the step's pair on the line, nothing crossing: both count, each way.
  EXPECT_EQ(search(code(0, 0, 0, 0), code(0, 0, 1, 1)), 2);
  EXPECT_EQ(search(33 + code(0, 0, 0, 0), code(0, 0, 1, 1)), 2);
  // Only the landed-on pixel on the line: one.
  EXPECT_EQ(search(code(0, 0, 0, 0), code(0, 0, 0, 1)), 1);
  // Towards the line's end, a crossing edge at the landed-on pixel stops the count there.
  EXPECT_EQ(search(33 + code(0, 1, 0, 0), code(0, 0, 1, 1)), 0);
  for (uint8_t value : kSmaaSearchTexture) EXPECT_LE(value, 2);
}
