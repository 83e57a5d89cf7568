#include "shade/ShadeGlyph.h"

#include <array>
#include <cstddef>

namespace termshade {
namespace {

// Eighths 1..8 of the cell inked; bound k is round(255 sqrt(k (k + 1)) / 8),
// OrderedDither::RankThreshold(k, 8) (a test holds them equal).
constexpr std::array<char32_t, 8> kBars{U'\u258F', U'\u258E', U'\u258D', U'\u258C',
                                        U'\u258B', U'\u258A', U'\u2589', U'\u2588'};
constexpr std::array<int, 7> kBounds{45, 78, 110, 143, 175, 207, 239};

}  // namespace

char32_t ShadeGlyph(uint8_t intensity) {
  std::size_t level = 0;
  while (level < kBounds.size() && intensity >= kBounds[level]) ++level;
  return kBars[level];
}

}  // namespace termshade
