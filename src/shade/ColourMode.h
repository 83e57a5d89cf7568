#pragma once

#include <optional>
#include <string_view>

namespace termshade {

/// How cells are coloured (SPEC 9 --color): not at all, with the nearest
/// of the 16 ANSI colours, with the nearest entry of the xterm 256-colour
/// cube or grey ramp, or with 24-bit colour. kAuto is resolved from the
/// environment by AutoColourMode. The order is from fewest colours to most.
enum class ColourMode { kNone, k16, k256, kTrueColour, kAuto };

/// `none`, `16`, `256`, `truecolor` (also `24bit`) or `auto`.
std::optional<ColourMode> ParseColourMode(std::string_view name);
std::string_view ColourModeName(ColourMode mode);

/// What `auto` means for a terminal: none when NO_COLOR is set (non-empty),
/// truecolor when COLORTERM says truecolor/24bit or terminfo has direct
/// colour (RGB or Tc), 256 when terminfo has 256 colours or more, 16 when
/// it has 8 or more, else none.
ColourMode AutoColourMode(std::string_view noColor, std::string_view colorTerm, int terminfoColours,
                          bool terminfoDirect);

}  // namespace termshade
