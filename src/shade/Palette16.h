#pragma once

#include <array>

#include "shade/Background.h"
#include "shade/CellColour.h"

namespace termshade {

/// The 16 ANSI colours as xterm shows them by default (0-7 normal, 8-15
/// bright). A terminal may show others; the 16-colour mode picks with these.
constexpr std::array<Srgb8, 16> kXtermPalette16{{{0, 0, 0},
                                                 {205, 0, 0},
                                                 {0, 205, 0},
                                                 {205, 205, 0},
                                                 {0, 0, 238},
                                                 {205, 0, 205},
                                                 {0, 205, 205},
                                                 {229, 229, 229},
                                                 {127, 127, 127},
                                                 {255, 0, 0},
                                                 {0, 255, 0},
                                                 {255, 255, 0},
                                                 {92, 92, 255},
                                                 {255, 0, 255},
                                                 {0, 255, 255},
                                                 {255, 255, 255}}};

/// The ANSI colour (0..15) for a shade: among the entries of the face's hue
/// (`face`: its normal and bright entry and black; for a face of little
/// chroma the greys 0, 8, 7 and 15), the one nearest the shade's CIELAB
/// lightness, so shades step through dark and bright entries and keep
/// their hue. Only entries that keep kMinBackgroundContrast against the
/// background take part.
int Nearest16Colour(Srgb8 shade, Srgb8 face, Background background = Background::kDark);

}  // namespace termshade
