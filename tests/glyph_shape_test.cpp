// ShapeOfGlyph inverts PatternGlyph: the parts a glyph inks, for the SVG export.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "shade/BlockGlyphs.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/GlyphInk.h"
#include "shade/GlyphShape.h"
#include "shade/ShadeGlyph.h"

namespace termshade {
namespace {

// The share of the cell a shape inks.
double InkedShare(const GlyphShape& shape) {
  return static_cast<double>(__builtin_popcount(shape.pattern)) / shape.grid.Count();
}

TEST(GlyphShape, EveryPatternGlyphHasTheShapeItWasMadeFrom) {
  for (const GlyphMode mode :
       {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants, GlyphMode::kBraille}) {
    const SampleGrid grid = ModeSampleGrid(mode);
    for (SamplePattern pattern = 1; pattern < (SamplePattern{1} << grid.Count()); ++pattern) {
      const char32_t glyph = PatternGlyph(mode, pattern);
      const GlyphShape* shape = ShapeOfGlyph(glyph);
      ASSERT_NE(shape, nullptr) << GlyphModeName(mode) << " pattern " << pattern;
      // The same glyph from a coarser grid (U+2588, U+258C, ...) covers the same area.
      EXPECT_DOUBLE_EQ(InkedShare(*shape),
                       static_cast<double>(__builtin_popcount(pattern)) / grid.Count());
      if (shape->grid == grid) {
        EXPECT_EQ(shape->pattern, pattern);
      }
      EXPECT_EQ(shape->dots, mode == GlyphMode::kBraille);
    }
  }
}

// The share of a glyph's 8 x 16 ink pixels on which its shape agrees with
// the measured ink (inked: more than half ink).
double AgreementWithInk(char32_t glyph, const GlyphShape& shape) {
  const InkMap* ink = DefaultInkTable().Find(glyph);
  if (ink == nullptr) return 0.0;
  int agree = 0;
  for (int y = 0; y < kInkRows; ++y) {
    for (int x = 0; x < kInkColumns; ++x) {
      const int part = (y * shape.grid.down / kInkRows) * shape.grid.across +
                       x * shape.grid.across / kInkColumns;
      const bool shaped = (shape.pattern >> part) & 1U;
      agree += shaped == ((*ink)[static_cast<size_t>(y * kInkColumns + x)] > 127) ? 1 : 0;
    }
  }
  return static_cast<double>(agree) / (kInkRows * kInkColumns);
}

TEST(GlyphShape, EighthBlocksAreRectanglesOfTheirInk) {
  std::vector<char32_t> eighths{U'\u2594', U'\u2595'};
  for (char32_t glyph = U'\u2581'; glyph <= U'\u2587'; ++glyph) eighths.push_back(glyph);
  for (char32_t glyph = U'\u2589'; glyph <= U'\u258F'; ++glyph) eighths.push_back(glyph);
  for (const char32_t glyph : eighths) {
    const GlyphShape* shape = ShapeOfGlyph(glyph);
    ASSERT_NE(shape, nullptr) << static_cast<uint32_t>(glyph);
    EXPECT_GE(AgreementWithInk(glyph, *shape), 0.9) << static_cast<uint32_t>(glyph);
  }
  EXPECT_DOUBLE_EQ(InkedShare(*ShapeOfGlyph(U'\u258F')), 1.0 / 8);
  EXPECT_DOUBLE_EQ(InkedShare(*ShapeOfGlyph(U'\u2589')), 7.0 / 8);
  EXPECT_DOUBLE_EQ(InkedShare(*ShapeOfGlyph(U'\u2581')), 1.0 / 8);
}

// Every glyph a mono frame can hold is drawn as shapes in an SVG, not as text.
TEST(GlyphShape, EveryMonoGlyphHasAShape) {
  for (int shade = 0; shade < 256; ++shade) {
    EXPECT_NE(ShapeOfGlyph(ShadeGlyph(static_cast<uint8_t>(shade))), nullptr) << shade;
  }
  std::mt19937 random(7);
  for (const GlyphMode mode : {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants}) {
    const SampleGrid parts = ModeSampleGrid(mode);
    const BlurredGlyphMatch match(mode, parts);
    std::vector<uint8_t> values(static_cast<size_t>(parts.Count()));
    for (int round = 0; round < 3000; ++round) {
      for (uint8_t& v : values) v = random() % 3 == 0 ? 0 : static_cast<uint8_t>(random() % 256);
      const char32_t glyph = match.Nearest(values.data());
      EXPECT_NE(ShapeOfGlyph(glyph), nullptr) << static_cast<uint32_t>(glyph);
    }
  }
}

TEST(GlyphShape, TextGlyphsAndBlankHaveNone) {
  for (const char32_t glyph : {U' ', U'@', U'.', U'#', U'\u00e9', U'\u2500', U'\u2591'})
    EXPECT_EQ(ShapeOfGlyph(glyph), nullptr) << static_cast<uint32_t>(glyph);
}

}  // namespace
}  // namespace termshade
