#pragma once

#include <cstdint>

namespace termshade {

/// The glyph of a covered cell's shade of `intensity` (0..255) without colour:
/// a left bar of 1 to 7 eighths of the cell (U+258F..2589) or the full block,
/// never blank (SPEC 4). A bar repeats every cell across and not at all down,
/// so next to its like it looks flat grey from a step back: eight levels where
/// the shade glyphs U+2591..2593 give three. The bound between two levels is
/// their geometric mean (where SSIM's luminance term is equal), in integers.
char32_t ShadeGlyph(uint8_t intensity);

}  // namespace termshade
