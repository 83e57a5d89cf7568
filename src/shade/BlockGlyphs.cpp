#include "shade/BlockGlyphs.h"

#include <array>

namespace termshade {
namespace {

// Quadrants by pattern: bit 0 top left, 1 top right, 2 bottom left, 3 bottom right.
constexpr std::array<char32_t, 16> kQuadrants{
    U' ',      U'\u2598', U'\u259D', U'\u2580', U'\u2596', U'\u258C', U'\u259E', U'\u259B',
    U'\u2597', U'\u259A', U'\u2590', U'\u259C', U'\u2584', U'\u2599', U'\u259F', U'\u2588'};

constexpr SamplePattern kLeftColumn = 0b010101;
constexpr SamplePattern kRightColumn = 0b101010;

char32_t Sextant(SamplePattern pattern) {
  if (pattern == 0) return U' ';
  if (pattern == kLeftColumn) return U'\u258C';
  if (pattern == kRightColumn) return U'\u2590';
  if (pattern == 0b111111) return U'\u2588';
  // U+1FB00 is pattern 1; the block skips the two half-cell columns.
  const uint32_t skipped = (pattern > kLeftColumn ? 1U : 0U) + (pattern > kRightColumn ? 1U : 0U);
  return static_cast<char32_t>(0x1FB00 + pattern - 1 - skipped);
}

// Braille dots 1-8 by sample (row-major, 2 across): dots 1 2 3 7 run down the
// left column, 4 5 6 8 down the right one.
constexpr std::array<uint32_t, 8> kBrailleBit{0x01, 0x08, 0x02, 0x10, 0x04, 0x20, 0x40, 0x80};

char32_t Braille(SamplePattern pattern) {
  if (pattern == 0) return U' ';  // the background stays blank, not U+2800
  uint32_t dots = 0;
  for (size_t i = 0; i < kBrailleBit.size(); ++i) {
    if ((pattern >> i) & 1U) dots |= kBrailleBit[i];
  }
  return static_cast<char32_t>(0x2800 + dots);
}

}  // namespace

char32_t PatternGlyph(GlyphMode mode, SamplePattern pattern) {
  switch (mode) {
    case GlyphMode::kBlocks:
      return kQuadrants[(pattern & 1U ? 3U : 0U) | (pattern & 2U ? 12U : 0U)];
    case GlyphMode::kQuadrants:
      return kQuadrants[pattern & 15U];
    case GlyphMode::kSextants:
      return Sextant(pattern & 63U);
    case GlyphMode::kBraille:
      return Braille(pattern & 255U);
    default:
      return pattern != 0 ? U'\u2588' : U' ';
  }
}

}  // namespace termshade
