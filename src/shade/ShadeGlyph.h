#pragma once

#include <cstdint>

namespace termshade {

/// The shade glyph nearest a shade of `intensity` (0..255) without colour:
/// light, medium or dark shade (U+2591..2593, a quarter, a half and three
/// quarters ink) or the full block; never blank (SPEC 4), so the darkest shade
/// is light shade. Mono terminals draw the shades as a fine stipple that looks
/// grey from a step back, with no pattern the size of a cell.
char32_t ShadeGlyph(uint8_t intensity);

}  // namespace termshade
