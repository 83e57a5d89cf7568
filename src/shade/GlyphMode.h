#pragma once

#include <optional>
#include <string_view>

namespace termshade {

/// How a cell shows what lies inside it (SPEC 11).
enum class GlyphMode { kRamp, kAscii, kBlocks, kQuadrants, kSextants, kBraille };

constexpr int kGlyphModeCount = 6;

std::string_view GlyphModeName(GlyphMode mode);
std::optional<GlyphMode> ParseGlyphMode(std::string_view name);
/// The next mode in the order above, wrapping (the viewer's key cycles with it).
GlyphMode NextGlyphMode(GlyphMode mode);
/// True for the modes drawn with characters outside ASCII (they need a UTF-8 terminal).
bool NeedsUtf8(GlyphMode mode);

/// The mode a viewer starts in when none was asked for: sextants where the
/// terminal is known to draw them (kitty, foot, WezTerm, ghostty, contour) with
/// colour and UTF-8, quadrants elsewhere with both, shape-matched ascii without
/// colour (its glyphs carry the shade) or outside a UTF-8 locale.
GlyphMode PickGlyphMode(bool utf8, bool colour, std::string_view term,
                        std::string_view termProgram);

/// Samples per cell: `across` columns by `down` rows at the centers of a regular grid.
struct SampleGrid {
  int across = 1;
  int down = 1;
  int Count() const { return across * down; }
  bool operator==(const SampleGrid&) const = default;
};

/// The grid a mode's glyphs are chosen from: ramp 1x1, ascii 2x4, blocks 1x2,
/// quadrants 2x2, sextants 2x3, braille 2x4.
SampleGrid ModeSampleGrid(GlyphMode mode);
/// With two colours, the block modes show each part of the cell in the mean
/// colour of that part (an area average, as chafa does for images): each
/// part of ModeSampleGrid is sampled this many times across and down.
/// {1, 1} for the other modes.
SampleGrid ColourSubsamples(GlyphMode mode);

}  // namespace termshade
