#include "shade/TerminalTheme.h"

#include <cstdio>

namespace termshade {

TerminalTheme ThemeFor(Background background) {
  TerminalTheme theme;
  if (background == Background::kLight) {
    theme.foreground = {0, 0, 0};
    theme.background = {255, 255, 255};
  }
  return theme;
}

Srgb8 ShownColour(const TermColour& colour, const TerminalTheme& theme, bool background) {
  switch (colour.kind) {
    case TermColour::Kind::kIndexed:
      return colour.index < theme.palette.size() ? theme.palette[colour.index]
                                                 : Palette256Colour(colour.index);
    case TermColour::Kind::kRgb:
      return colour.rgb;
    case TermColour::Kind::kDefault:
      break;
  }
  return background ? theme.background : theme.foreground;
}

std::string HexColour(Srgb8 colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", colour.r, colour.g, colour.b);
  return text;
}

}  // namespace termshade
