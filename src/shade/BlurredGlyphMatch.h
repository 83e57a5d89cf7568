#pragma once

#include <cstdint>
#include <vector>

#include "shade/GlyphMode.h"

namespace termshade {

/// The glyph of a silhouette cell without colour (some parts covered, some
/// background): of the mode's own patterns and the block elements (lower
/// eighths U+2581..2587, left eighths U+2589..258F, then U+2590, U+2594,
/// U+2595, U+2580, U+2588), the one whose ink is nearest the
/// parts' shades after a blur like the fidelity measure's (a Gaussian of
/// 4 px, then 1.5 px, at 8 x 16 px a cell; DefaultInkTable's ink). Least
/// squares over the cell's pixels taken alone: sum over i, j of d_i d_j g(i - j),
/// d = ink - shade. A thin edge becomes a thin bar rather than a dithered
/// corner. Integer arithmetic; ties go to the first candidate (the mode's
/// patterns by number, then the block elements in the order above).
class BlurredGlyphMatch {
 public:
  /// Candidates for `mode`, targets on a grid of `parts` a cell.
  BlurredGlyphMatch(GlyphMode mode, SampleGrid parts);

  GlyphMode Mode() const { return mode_; }
  SampleGrid Parts() const { return parts_; }
  /// The candidate nearest the parts' shades (0..255 each, background 0, row-major).
  char32_t Nearest(const uint8_t* values) const;

 private:
  GlyphMode mode_;
  SampleGrid parts_;
  std::vector<char32_t> glyphs_;
  /// Per glyph: sum over pixels i, j of ink_i ink_j g(i - j).
  std::vector<int64_t> self_;
  /// Per glyph and part: sum over pixels i, and j in the part, of ink_i g(i - j).
  std::vector<int64_t> cross_;
};

}  // namespace termshade
