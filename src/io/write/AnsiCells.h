#pragma once

#include <span>
#include <string>
#include <vector>

#include "raster/CellBuffer.h"
#include "shade/CellColour.h"

namespace termshade {

/// One cell of an ansi frame as a terminal shows it once the frame is drawn:
/// its glyph and the colours it is drawn in.
struct AnsiCell {
  char32_t glyph = U' ';
  TermColour foreground;  ///< a blank cell keeps the one its row had before it
  TermColour background;
  bool operator==(const AnsiCell&) const = default;
};

/// An ansi frame cell by cell, row-major: what AppendAnsiFrame draws, before
/// it becomes bytes (and what AnsiFrameDiff compares).
class AnsiCells {
 public:
  void Resize(int widthCells, int heightCells);
  int WidthCells() const { return widthCells_; }
  int HeightCells() const { return heightCells_; }
  AnsiCell& At(int col, int row) { return cells_[static_cast<size_t>(row) * widthCells_ + col]; }
  const AnsiCell& At(int col, int row) const {
    return cells_[static_cast<size_t>(row) * widthCells_ + col];
  }
  bool operator==(const AnsiCells&) const = default;

 private:
  int widthCells_ = 0;
  int heightCells_ = 0;
  std::vector<AnsiCell> cells_;
};

/// The cells of a frame in its faces' colours, as AppendAnsiFrame describes
/// them; resizes `out` to the frame.
void FillAnsiCells(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                   ColourMode mode, AnsiCells& out, Background background = Background::kDark);

/// The ansi dump of the cells: rows ended by '\n', each colour set where it
/// changes along its row (a row starts in the terminal's colours), a row
/// that set one ended with a reset.
void AppendAnsiRows(const AnsiCells& cells, std::string& out);

}  // namespace termshade
