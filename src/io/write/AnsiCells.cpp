#include "io/write/AnsiCells.h"

#include "io/write/FrameFormats.h"
#include "shade/Utf8.h"

namespace termshade {

void AnsiCells::Resize(int widthCells, int heightCells) {
  widthCells_ = widthCells;
  heightCells_ = heightCells;
  cells_.assign(static_cast<size_t>(widthCells) * heightCells, AnsiCell{});
}

void FillAnsiCells(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                   ColourMode mode, AnsiCells& out, Background background) {
  CellColourMap colours(faceColours, levelCount, mode, background);
  const bool coloured = mode != ColourMode::kNone;
  out.Resize(cells.WidthCells(), cells.HeightCells());
  for (int row = 0; row < cells.HeightCells(); ++row) {
    TermColour foreground;  // the terminal's until a cell sets one
    for (int col = 0; col < cells.WidthCells(); ++col) {
      AnsiCell& cell = out.At(col, row);
      cell.glyph = cells.Glyph(col, row);
      const int level = cells.Level(col, row);
      if (level >= 0 && coloured) {  // a blank cell keeps the colour it has
        foreground = colours.ForFace(cells.FaceNumber(col, row), level, cells.ForeAlbedo(col, row));
      }
      cell.foreground = foreground;
      // Two-colour glyph modes give a background face; others keep the terminal's.
      const int backLevel = cells.BackLevel(col, row);
      cell.background = backLevel >= 0 && coloured
                            ? colours.ForFace(cells.BackFaceNumber(col, row), backLevel,
                                              cells.BackAlbedo(col, row))
                            : TermColour{};
    }
  }
}

void AppendAnsiRows(const AnsiCells& cells, std::string& out) {
  for (int row = 0; row < cells.HeightCells(); ++row) {
    TermColour current, currentBack;  // the terminal's defaults until a cell sets one
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const AnsiCell& cell = cells.At(col, row);
      if (!(cell.foreground == current)) AppendForegroundSgr(cell.foreground, out);
      current = cell.foreground;
      if (!(cell.background == currentBack)) AppendBackgroundSgr(cell.background, out);
      currentBack = cell.background;
      AppendUtf8(out, cell.glyph);
    }
    if (!(current == TermColour{}) || !(currentBack == TermColour{})) out += "\x1b[0m";
    out += '\n';
  }
}

}  // namespace termshade
