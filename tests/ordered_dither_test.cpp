// The ordered dither (src/shade/OrderedDither) and the glyph stage's mono
// pattern modes that use it: shades become ink density at screen-fixed
// thresholds, and a covered cell is never blank.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "raster/FramePlan.h"
#include "raster/GlyphStage.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/OrderedDither.h"

namespace termshade {
namespace {

int InkedInTile(const OrderedDither& dither, int intensity, int x0, int y0) {
  int inked = 0;
  for (int y = 0; y < dither.Side(); ++y) {
    for (int x = 0; x < dither.Side(); ++x) {
      inked += dither.Inks(static_cast<uint8_t>(intensity), x0 + x, y0 + y) ? 1 : 0;
    }
  }
  return inked;
}

TEST(OrderedDither, EveryLevelInksItsShareOfEveryTile) {
  for (int order = 1; order <= 4; ++order) {
    const OrderedDither dither(order);
    const int tile = dither.Side() * dither.Side();
    int previous = 0;
    for (int v = 0; v < 256; ++v) {
      int below = 0;  // ranks whose threshold v exceeds
      for (int r = 0; r < tile; ++r) below += v > OrderedDither::RankThreshold(r, tile) ? 1 : 0;
      // Any tile-sized window of the repeating pattern holds each threshold once.
      for (const auto& [x0, y0] : {std::pair{0, 0}, std::pair{3, 5}, std::pair{17, 2}}) {
        const int inked = InkedInTile(dither, v, x0, y0);
        ASSERT_EQ(inked, below) << "order " << order << " v " << v;
        ASSERT_LE(std::abs(inked - v * tile / 255.0), 1.0) << "order " << order << " v " << v;
        ASSERT_GE(inked, previous);
        if (x0 == 0) previous = inked;
      }
    }
    EXPECT_EQ(InkedInTile(dither, 0, 0, 0), 0);
    EXPECT_EQ(InkedInTile(dither, 255, 0, 0), tile);
  }
}

// Between r and r + 1 quarters inked the bound is their geometric mean, where
// SSIM's luminance term is the same for both; the first at half a quarter.
TEST(OrderedDither, TwoByTwoThresholdsAreGeometricMeans) {
  EXPECT_EQ(OrderedDither::RankThreshold(0, 4), 31);
  EXPECT_EQ(OrderedDither::RankThreshold(1, 4), 90);   // 255 sqrt(2) / 4 = 90.2
  EXPECT_EQ(OrderedDither::RankThreshold(2, 4), 156);  // 255 sqrt(6) / 4 = 156.2
  EXPECT_EQ(OrderedDither::RankThreshold(3, 4), 221);  // 255 sqrt(12) / 4 = 220.8
  const OrderedDither dither(1);
  EXPECT_EQ(dither.Threshold(0, 0), 31);
  EXPECT_EQ(dither.Threshold(1, 1), 90);
  EXPECT_EQ(dither.Threshold(1, 0), 156);
  EXPECT_EQ(dither.Threshold(0, 1), 221);
}

// A dark braille cell inks one dot: the top tile's in even columns and the
// bottom tile's in odd ones, so the dots fall on a diagonal lattice.
TEST(OrderedDither, TheDarkestDotAlternatesTilesByColumn) {
  const OrderedDither dither(1);
  const std::vector<uint8_t> dark(8, 10);
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 3; ++row) {
      const SamplePattern ink = dither.CellInk(dark.data(), 0xFF, {2, 4}, col, row);
      EXPECT_EQ(ink, col % 2 == 0 ? 0x01U : 0x10U) << col << "," << row;
    }
  }
  // With one of the two covered, that one whatever the column.
  EXPECT_EQ(dither.CellInk(dark.data(), 0x0F, {2, 4}, 1, 0), 0x01U);
  EXPECT_EQ(dither.CellInk(dark.data(), 0xF0, {2, 4}, 0, 0), 0x10U);
}

TEST(OrderedDither, ThresholdsDependOnTheScreenPositionAlone) {
  const OrderedDither dither(3);
  std::set<int> seen;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      seen.insert(dither.Threshold(x, y));
      // The pattern repeats every side samples, and a copy reads the same.
      EXPECT_EQ(dither.Threshold(x, y), dither.Threshold(x + 8, y));
      EXPECT_EQ(dither.Threshold(x, y), dither.Threshold(x, y + 80));
      EXPECT_EQ(dither.Threshold(x, y), OrderedDither(3).Threshold(x, y));
    }
  }
  EXPECT_EQ(seen.size(), 64U);  // 64 distinct levels
  // Bayer: the lowest half of the thresholds is a checkerboard.
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) EXPECT_EQ(dither.Threshold(x, y) < 127, (x + y) % 2 == 0);
  }
}

TEST(OrderedDither, ACoveredCellIsNeverBlank) {
  const OrderedDither dither(3);
  const std::vector<uint8_t> dark(8, 0);
  for (SamplePattern covered = 1; covered < 256; ++covered) {
    for (int col = 0; col < 4; ++col) {
      const SamplePattern ink = dither.CellInk(dark.data(), covered, {2, 4}, col, 1);
      ASSERT_EQ(std::popcount(ink), 1);
      ASSERT_NE(ink & covered, 0U);
    }
  }
  EXPECT_EQ(dither.CellInk(dark.data(), 0, {2, 4}, 0, 0), 0U);
}

constexpr int kCols = 16, kRows = 8;

// Every cell of a pattern mode's mono frame shows face 1 in all samples, or
// (rightHalf) only the cells from kCols / 2 on.
CellBuffer MonoFrame(GlyphMode mode, uint8_t intensity, bool rightHalf = false, uint32_t face = 1) {
  RenderOptions options;
  options.glyphs = mode;
  options.twoColour = false;
  const GlyphPlan plan = PlanGlyphs(options);
  SampleFrame frame;
  frame.Begin(kCols, kRows, plan.pattern);
  const auto perCell = static_cast<size_t>(plan.pattern.Count());
  for (size_t cell = 0; cell < frame.CellCount(); ++cell) {
    if (rightHalf && static_cast<int>(cell % kCols) < kCols / 2) continue;
    frame.Touch(cell);
    for (size_t n = 0; n < perCell; ++n) {
      frame.FaceData()[cell * perCell + n] = face;
      frame.DepthData()[cell * perCell + n] = 0.5F;
    }
  }
  const std::vector<uint8_t> intensities(4, intensity);
  CellBuffer cells(kCols, kRows);
  DepthBuffer depth;
  depth.Resize(kCols, kRows);
  GlyphStage stage;
  stage.Compose({frame, intensities}, plan, cells, depth);
  return cells;
}

constexpr GlyphMode kPatternModes[] = {GlyphMode::kBlocks, GlyphMode::kQuadrants,
                                       GlyphMode::kSextants, GlyphMode::kBraille};

// Inked samples of a cell's glyph, by decoding it back through PatternGlyph.
int InkedSamples(GlyphMode mode, char32_t glyph) {
  const int count = ModeSampleGrid(mode).Count();
  for (SamplePattern p = 0; p < (SamplePattern{1} << count); ++p) {
    if (PatternGlyph(mode, p) == glyph) return std::popcount(p);
  }
  return -1;
}

TEST(GlyphStageMono, HalfShadeIsACheckerboardOrAHalfBlock) {
  for (GlyphMode mode : kPatternModes) {
    const CellBuffer cells = MonoFrame(mode, 128);
    const int perCell = ModeSampleGrid(mode).Count();
    for (int row = 0; row < kRows; ++row) {
      for (int col = 0; col < kCols; ++col) {
        if (mode == GlyphMode::kBraille) {  // half the dots, in a checkerboard
          ASSERT_EQ(InkedSamples(mode, cells.Glyph(col, row)), perCell / 2) << col << "," << row;
          ASSERT_EQ(cells.Glyph(col, row), U'\u2895');  // dots 1, 3, 5, 8
        } else {  // a covered cell of the block modes: the left half block
          ASSERT_EQ(cells.Glyph(col, row), U'\u258C') << GlyphModeName(mode);
        }
      }
    }
  }
}

TEST(GlyphStageMono, CoveredBlockCellsAreTheNearestShadeGlyph) {
  // Left bars of 1..7 eighths and the full block, at integer geometric-mean bounds.
  const std::pair<int, char32_t> expected[] = {
      {0, U'\u258F'},   {44, U'\u258F'},  {45, U'\u258E'},  {77, U'\u258E'},
      {78, U'\u258D'},  {109, U'\u258D'}, {110, U'\u258C'}, {142, U'\u258C'},
      {143, U'\u258B'}, {174, U'\u258B'}, {175, U'\u258A'}, {206, U'\u258A'},
      {207, U'\u2589'}, {238, U'\u2589'}, {239, U'\u2588'}, {255, U'\u2588'}};
  // The bounds are the dither's rank thresholds of 8 (its geometric means).
  for (int k = 1; k <= 7; ++k) {
    EXPECT_EQ(expected[2 * k].first, OrderedDither::RankThreshold(k, 8)) << k;
  }
  for (GlyphMode mode : {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants}) {
    for (const auto& [intensity, glyph] : expected) {
      const CellBuffer cells = MonoFrame(mode, static_cast<uint8_t>(intensity));
      for (int row = 0; row < kRows; ++row) {
        for (int col = 0; col < kCols; ++col) {
          ASSERT_EQ(cells.Glyph(col, row), glyph) << GlyphModeName(mode) << " " << intensity;
          // The tones are the covered samples' whatever the glyph.
          ASSERT_EQ(cells.FaceNumber(col, row), 1U);
          ASSERT_EQ(cells.Intensity(col, row), intensity);
        }
      }
    }
  }
}

TEST(GlyphStageMono, FullBrailleIsAllDotsAndNoShadeOneDot) {
  const CellBuffer full = MonoFrame(GlyphMode::kBraille, 255);
  const CellBuffer none = MonoFrame(GlyphMode::kBraille, 0);
  for (int row = 0; row < kRows; ++row) {
    for (int col = 0; col < kCols; ++col) {
      ASSERT_EQ(InkedSamples(GlyphMode::kBraille, full.Glyph(col, row)), 8);
      ASSERT_EQ(InkedSamples(GlyphMode::kBraille, none.Glyph(col, row)), 1);
      ASSERT_EQ(none.FaceNumber(col, row), 1U);
      ASSERT_EQ(full.Intensity(col, row), 255);
    }
  }
}

// A silhouette cell (some samples background) is a dithered pattern of its
// covered samples in braille, the matcher's glyph in the block modes; never blank.
TEST(GlyphStageMono, SilhouetteCellsAreDitheredOrMatched) {
  for (GlyphMode mode : kPatternModes) {
    for (int v : {0, 128, 255}) {
      RenderOptions options;
      options.glyphs = mode;
      options.twoColour = false;
      const GlyphPlan plan = PlanGlyphs(options);
      SampleFrame frame;
      frame.Begin(1, 1, plan.pattern);
      frame.Touch(0);
      frame.FaceData()[0] = 1;  // the first sample alone covered
      frame.DepthData()[0] = 0.5F;
      const std::vector<uint8_t> intensities(1, static_cast<uint8_t>(v));
      CellBuffer cells(1, 1);
      DepthBuffer depth;
      depth.Resize(1, 1);
      GlyphStage stage;
      stage.Compose({frame, intensities}, plan, cells, depth);
      std::array<uint8_t, 8> values{};
      values[0] = static_cast<uint8_t>(v);
      const char32_t expected = mode == GlyphMode::kBraille
                                    ? PatternGlyph(mode, 1)
                                    : BlurredGlyphMatch(mode, plan.pattern).Nearest(values.data());
      EXPECT_EQ(cells.Glyph(0, 0), expected) << GlyphModeName(mode) << " " << v;
      EXPECT_NE(cells.Glyph(0, 0), U' ') << GlyphModeName(mode) << " " << v;
    }
  }
}

TEST(GlyphStageMono, ACellKeepsItsGlyphWhenTheModelMovesUnderIt) {
  // The same shade at the same cells gives the same glyphs whichever face
  // shows it and wherever the rest of the model is.
  for (GlyphMode mode : kPatternModes) {
    for (int v : {20, 77, 128, 200}) {
      const CellBuffer whole = MonoFrame(mode, static_cast<uint8_t>(v));
      const CellBuffer half = MonoFrame(mode, static_cast<uint8_t>(v), true, 3);
      for (int row = 0; row < kRows; ++row) {
        for (int col = kCols / 2; col < kCols; ++col) {
          ASSERT_EQ(whole.Glyph(col, row), half.Glyph(col, row)) << GlyphModeName(mode) << v;
        }
      }
    }
  }
}

TEST(GlyphStageMono, OnlyTheMonoPatternModesDitherAndOnlyTheirBlockModesShade) {
  for (int m = 0; m < kGlyphModeCount; ++m) {
    for (bool colour : {false, true}) {
      RenderOptions options;
      options.glyphs = static_cast<GlyphMode>(m);
      options.twoColour = colour;
      const bool pattern =
          options.glyphs != GlyphMode::kRamp && options.glyphs != GlyphMode::kAscii;
      EXPECT_EQ(PlanGlyphs(options).ditherOrder != 0, pattern && !colour)
          << GlyphModeName(options.glyphs) << colour;
      EXPECT_EQ(PlanGlyphs(options).shadeGlyphs,
                pattern && !colour && options.glyphs != GlyphMode::kBraille)
          << GlyphModeName(options.glyphs) << colour;
    }
  }
}

}  // namespace
}  // namespace termshade
