#pragma once

#include <array>
#include <string>

#include "shade/Background.h"
#include "shade/CellColour.h"
#include "shade/Palette16.h"

namespace termshade {

/// The colours a terminal gives what a frame leaves to it: its default
/// foreground and background and its 16-colour palette. Exports that stand
/// in for a terminal (SVG pictures, asciicast recordings) draw with it; the
/// default is a black terminal with xterm's palette (as tools/ansi2png.py).
struct TerminalTheme {
  Srgb8 foreground{192, 192, 192};
  Srgb8 background{0, 0, 0};
  std::array<Srgb8, 16> palette = kXtermPalette16;
};

/// The default theme for a dark terminal, or black on white for a light one.
TerminalTheme ThemeFor(Background background);

/// The sRGB colour a terminal with `theme` shows for `colour`, as a glyph's
/// ink (foreground) or a cell's background.
Srgb8 ShownColour(const TermColour& colour, const TerminalTheme& theme, bool background);

/// "#rrggbb", lower case.
std::string HexColour(Srgb8 colour);

}  // namespace termshade
