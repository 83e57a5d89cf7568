#include "shade/GlyphShape.h"

#include <array>
#include <unordered_map>

namespace termshade {
namespace {

// Every glyph of the pattern modes, by inverting PatternGlyph once. Braille
// first (its glyphs are its own), then the finer grids: a glyph two modes
// share (U+2588, U+258C, ...) covers the same area in either.
std::unordered_map<char32_t, GlyphShape> BuildShapes() {
  std::unordered_map<char32_t, GlyphShape> shapes;
  constexpr std::array kModes{GlyphMode::kBraille, GlyphMode::kSextants, GlyphMode::kQuadrants,
                              GlyphMode::kBlocks};
  for (const GlyphMode mode : kModes) {
    const SampleGrid grid = ModeSampleGrid(mode);
    const SamplePattern patternCount = SamplePattern{1} << grid.Count();
    for (SamplePattern pattern = 1; pattern < patternCount; ++pattern) {
      const GlyphShape shape{grid, pattern, mode == GlyphMode::kBraille};
      shapes.try_emplace(PatternGlyph(mode, pattern), shape);
    }
  }
  return shapes;
}

}  // namespace

const GlyphShape* ShapeOfGlyph(char32_t glyph) {
  static const std::unordered_map<char32_t, GlyphShape> kShapes = BuildShapes();
  const auto found = kShapes.find(glyph);
  return found == kShapes.end() ? nullptr : &found->second;
}

}  // namespace termshade
