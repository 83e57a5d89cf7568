// ShapeOfGlyph inverts PatternGlyph: the parts a glyph inks, for the SVG export.
#include <gtest/gtest.h>

#include "shade/BlockGlyphs.h"
#include "shade/GlyphShape.h"

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

TEST(GlyphShape, TextGlyphsAndBlankHaveNone) {
  for (const char32_t glyph : {U' ', U'@', U'.', U'#', U'\u00e9', U'\u2500', U'\u2591'})
    EXPECT_EQ(ShapeOfGlyph(glyph), nullptr) << static_cast<uint32_t>(glyph);
}

}  // namespace
}  // namespace termshade
