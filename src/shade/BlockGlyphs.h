#pragma once

#include <cstdint>

#include "shade/GlyphMode.h"

namespace termshade {

/// A cell's inked samples as bits, row-major from the top left: bit (row x
/// across + col) of the mode's sample grid.
using SamplePattern = uint32_t;

/// The block-element or braille character that shows `pattern` exactly, for
/// blocks (1x2), quadrants (2x2), sextants (2x3) and braille (2x4); 0 blank.
/// Sextants use U+1FB00..1FB3B and, for the four patterns that block lacks,
/// blank, U+258C, U+2590 and U+2588.
char32_t PatternGlyph(GlyphMode mode, SamplePattern pattern);

}  // namespace termshade
