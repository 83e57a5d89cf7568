#pragma once

#include "shade/BlockGlyphs.h"
#include "shade/GlyphMode.h"

namespace termshade {

/// What a block-element, sextant or braille glyph draws, as inked parts of
/// a cell: the parts of `grid` set in `pattern` (bit row x across + col),
/// filled rectangles, or dots for braille.
struct GlyphShape {
  SampleGrid grid;
  SamplePattern pattern = 0;
  bool dots = false;  ///< braille: a dot at each set part's center
};

/// The shape of a glyph that PatternGlyph makes (blocks, quadrants, sextants,
/// braille) or of an eighth block (U+2581..2587, U+2589..258F, U+2594,
/// U+2595); null for any other character, a text glyph. Lives as long as the program.
const GlyphShape* ShapeOfGlyph(char32_t glyph);

}  // namespace termshade
