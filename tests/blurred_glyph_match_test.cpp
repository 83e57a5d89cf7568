// The silhouette cells' matcher (src/shade/BlurredGlyphMatch): the glyph
// whose ink is nearest a cell's part shades after the fidelity measure's blur.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "shade/BlockGlyphs.h"
#include "shade/BlurredGlyphMatch.h"

namespace termshade {
namespace {

TEST(BlurredGlyphMatch, FullInkPartsAreTheirOwnPattern) {
  for (GlyphMode mode : {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants}) {
    const SampleGrid grid = ModeSampleGrid(mode);
    const BlurredGlyphMatch match(mode, grid);
    const SamplePattern all = (SamplePattern{1} << grid.Count()) - 1;
    for (SamplePattern p = 1; p <= all; ++p) {
      std::array<uint8_t, 8> values{};
      for (int n = 0; n < grid.Count(); ++n) values[n] = ((p >> n) & 1U) != 0 ? 255 : 0;
      EXPECT_EQ(match.Nearest(values.data()), PatternGlyph(mode, p))
          << GlyphModeName(mode) << " pattern " << p;
    }
  }
}

TEST(BlurredGlyphMatch, DimEdgesBecomeThinBars) {
  const BlurredGlyphMatch quadrants(GlyphMode::kQuadrants, {2, 2});
  const std::array<uint8_t, 4> leftQuarter{64, 0, 64, 0};
  EXPECT_EQ(quadrants.Nearest(leftQuarter.data()), U'\u258F');  // left one eighth
  const BlurredGlyphMatch blocks(GlyphMode::kBlocks, {1, 2});
  const std::array<uint8_t, 2> dimBottom{0, 100};
  EXPECT_EQ(blocks.Nearest(dimBottom.data()), U'\u2582');  // lower one quarter
}

TEST(BlurredGlyphMatch, ADarkCoveredPartIsNeverBlank) {
  for (GlyphMode mode : {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants}) {
    const BlurredGlyphMatch match(mode, ModeSampleGrid(mode));
    const std::array<uint8_t, 8> dark{};
    EXPECT_NE(match.Nearest(dark.data()), U' ') << GlyphModeName(mode);
    EXPECT_EQ(match.Nearest(dark.data()), U'\u258F') << GlyphModeName(mode);  // the least ink
  }
}

TEST(BlurredGlyphMatch, TargetsOnAFinerGridThanTheModes) {
  // Quadrants on a forced 2 x 4 grid: the left column lit reads as the left half.
  const BlurredGlyphMatch match(GlyphMode::kQuadrants, {2, 4});
  const std::array<uint8_t, 8> left{255, 0, 255, 0, 255, 0, 255, 0};
  EXPECT_EQ(match.Nearest(left.data()), U'\u258C');
  EXPECT_EQ(match.Parts(), (SampleGrid{2, 4}));
  EXPECT_EQ(match.Mode(), GlyphMode::kQuadrants);
}

}  // namespace
}  // namespace termshade
