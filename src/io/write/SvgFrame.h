#pragma once

#include <span>
#include <string>

#include "geometry/Rgb.h"
#include "raster/CellBuffer.h"
#include "shade/ColourMode.h"
#include "shade/TerminalTheme.h"

namespace termshade {

/// Width of a cell in an SVG frame, in SVG user units (CSS pixels); its
/// height is this times the cell aspect.
constexpr double kSvgCellWidthPx = 8.0;

/// How an SVG frame is drawn: the cells' shape and the terminal it stands for.
struct SvgFrameStyle {
  double cellAspect = 2.0;  ///< cell height / cell width
  ColourMode colourMode = ColourMode::k256;
  Background background = Background::kDark;  ///< the shades' background (CellColour)
  TerminalTheme theme;                        ///< ThemeFor(background) as a rule
};

/// The frame as one standalone SVG document, drawn as a terminal shows the
/// ansi dump of the same frame: the theme's background, each two-colour
/// cell's background, block, quadrant and sextant glyphs as rectangles,
/// braille as dots, every other glyph as monospace text in its cell;
/// colours as the ansi dump sets them (the theme's foreground without colour).
void AppendSvgFrame(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                    const SvgFrameStyle& style, std::string& out);

}  // namespace termshade
