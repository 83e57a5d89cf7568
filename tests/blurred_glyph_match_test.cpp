// The silhouette cells' matcher (src/shade/BlurredGlyphMatch): the glyph
// whose ink is nearest a cell's part shades after the fidelity measure's blur.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "shade/BlockGlyphs.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/GlyphInk.h"

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

// The matcher's error, computed the slow way in floating point: each pixel's
// ink minus its part's shade, blurred twice as the fidelity measure blurs
// (Gaussians of 4 and 1.5 px: one of variance 18.25), squared and summed
// over the cell: sum over pixels i, j of d_i d_j exp(-|i - j|^2 / (4 x 18.25)).
double BlurredError(char32_t glyph, SampleGrid parts, const std::vector<uint8_t>& shades) {
  const InkMap* ink = DefaultInkTable().Find(glyph);
  std::array<double, kInkColumns * kInkRows> d{};
  for (int y = 0; y < kInkRows; ++y) {
    for (int x = 0; x < kInkColumns; ++x) {
      const int part = static_cast<int>((y + 0.5) * parts.down / kInkRows) * parts.across +
                       static_cast<int>((x + 0.5) * parts.across / kInkColumns);
      const double inked = ink != nullptr ? (*ink)[static_cast<size_t>(y * kInkColumns + x)] : 0;
      d[static_cast<size_t>(y * kInkColumns + x)] = inked - shades[static_cast<size_t>(part)];
    }
  }
  double error = 0.0;
  for (int i = 0; i < kInkColumns * kInkRows; ++i) {
    for (int j = 0; j < kInkColumns * kInkRows; ++j) {
      const int dx = i % kInkColumns - j % kInkColumns, dy = i / kInkColumns - j / kInkColumns;
      error += d[static_cast<size_t>(i)] * d[static_cast<size_t>(j)] *
               std::exp(-(dx * dx + dy * dy) / (4.0 * 18.25));
    }
  }
  return error;
}

// An independent reference: every candidate's error the slow way; the
// matcher's choice must be the least (up to the rounding of its integer weights).
TEST(BlurredGlyphMatch, AgreesWithTheBlurredErrorComputedTheSlowWay) {
  const std::u32string blockElements =
      U"\u2581\u2582\u2583\u2584\u2585\u2586\u2587\u2589\u258A\u258B\u258C\u258D"
      U"\u258E\u258F\u2590\u2594\u2595\u2580\u2588";
  std::mt19937 random(2026);
  for (GlyphMode mode : {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants}) {
    const SampleGrid grid = ModeSampleGrid(mode);
    const BlurredGlyphMatch match(mode, grid);
    std::vector<char32_t> candidates(blockElements.begin(), blockElements.end());
    for (SamplePattern p = 1; p < (SamplePattern{1} << grid.Count()); ++p) {
      candidates.push_back(PatternGlyph(mode, p));
    }
    std::vector<uint8_t> shades(static_cast<size_t>(grid.Count()));
    for (int round = 0; round < 40; ++round) {
      for (uint8_t& v : shades) v = random() % 3 == 0 ? 0 : static_cast<uint8_t>(random() % 256);
      double least = INFINITY, largest = 0.0;
      for (const char32_t glyph : candidates) {
        const double error = BlurredError(glyph, grid, shades);
        least = std::min(least, error);
        largest = std::max(largest, std::fabs(error));
      }
      const char32_t chosen = match.Nearest(shades.data());
      EXPECT_LE(BlurredError(chosen, grid, shades), least + 1e-3 * largest)
          << GlyphModeName(mode) << " round " << round << ": chose U+" << std::hex
          << static_cast<uint32_t>(chosen);
    }
  }
}

}  // namespace
}  // namespace termshade
