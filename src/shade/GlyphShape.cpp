#include "shade/GlyphShape.h"

#include <array>
#include <unordered_map>

namespace termshade {
namespace {

// The eighth blocks the mono modes draw with (ShadeGlyph, BlurredGlyphMatch):
// lower k eighths U+2581..2587, left k eighths U+2589..258F (U+2589 is 7),
// the upper eighth U+2594 and the right eighth U+2595.
void AddEighthBlocks(std::unordered_map<char32_t, GlyphShape>& shapes) {
  const SampleGrid across{8, 1}, down{1, 8};
  for (int k = 1; k <= 7; ++k) {
    const SamplePattern lowest = ((SamplePattern{1} << k) - 1) << (8 - k);
    shapes.try_emplace(static_cast<char32_t>(U'\u2580' + k), GlyphShape{down, lowest, false});
    const SamplePattern leftmost = (SamplePattern{1} << k) - 1;
    shapes.try_emplace(static_cast<char32_t>(U'\u2590' - k), GlyphShape{across, leftmost, false});
  }
  shapes.try_emplace(U'\u2594', GlyphShape{down, 1, false});
  shapes.try_emplace(U'\u2595', GlyphShape{across, SamplePattern{1} << 7, false});
}

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
  AddEighthBlocks(shapes);
  return shapes;
}

}  // namespace

const GlyphShape* ShapeOfGlyph(char32_t glyph) {
  static const std::unordered_map<char32_t, GlyphShape> kShapes = BuildShapes();
  const auto found = kShapes.find(glyph);
  return found == kShapes.end() ? nullptr : &found->second;
}

}  // namespace termshade
