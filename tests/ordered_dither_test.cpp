// The ordered dither (src/shade/OrderedDither) and the glyph stage's mono
// pattern modes that use it: shades become ink density at screen-fixed
// thresholds, and a covered cell is never blank.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "raster/FramePlan.h"
#include "raster/GlyphStage.h"
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
      // Any tile-sized window of the repeating pattern holds each threshold once.
      for (const auto& [x0, y0] : {std::pair{0, 0}, std::pair{3, 5}, std::pair{17, 2}}) {
        const int inked = InkedInTile(dither, v, x0, y0);
        ASSERT_LE(std::abs(inked - v * tile / 255.0), 0.5) << "order " << order << " v " << v;
        ASSERT_GE(inked, previous);
        if (x0 == 0) previous = inked;
      }
    }
    EXPECT_EQ(InkedInTile(dither, 0, 0, 0), 0);
    EXPECT_EQ(InkedInTile(dither, 255, 0, 0), tile);
  }
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

TEST(GlyphStageMono, HalfShadeIsACheckerboardOrMediumShade) {
  for (GlyphMode mode : kPatternModes) {
    const CellBuffer cells = MonoFrame(mode, 128);
    const int perCell = ModeSampleGrid(mode).Count();
    for (int row = 0; row < kRows; ++row) {
      for (int col = 0; col < kCols; ++col) {
        if (mode == GlyphMode::kBraille) {  // half the dots, in a checkerboard
          ASSERT_EQ(InkedSamples(mode, cells.Glyph(col, row)), perCell / 2) << col << "," << row;
          ASSERT_EQ(cells.Glyph(col, row), U'\u2895');  // dots 1, 3, 5, 8
        } else {  // a covered cell of the block modes: medium shade
          ASSERT_EQ(cells.Glyph(col, row), U'\u2592') << GlyphModeName(mode);
        }
      }
    }
  }
}

TEST(GlyphStageMono, CoveredBlockCellsAreTheNearestShadeGlyph) {
  const std::pair<int, char32_t> expected[] = {{0, U'\u2591'},   {95, U'\u2591'},  {96, U'\u2592'},
                                               {159, U'\u2592'}, {160, U'\u2593'}, {223, U'\u2593'},
                                               {224, U'\u2588'}, {255, U'\u2588'}};
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

// A silhouette cell (some samples background) stays a dithered pattern of
// its covered samples, never blank and never a shade glyph.
TEST(GlyphStageMono, SilhouetteCellsStayDithered) {
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
      EXPECT_EQ(cells.Glyph(0, 0), PatternGlyph(mode, 1)) << GlyphModeName(mode) << " " << v;
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
