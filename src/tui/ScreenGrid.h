#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "shade/CellColour.h"

namespace termshade {

/// How a screen cell looks besides its character.
enum class CellStyle : uint8_t {
  kPlain,    ///< the terminal's default colours (the model's background too)
  kReverse,  ///< status line and overlays
  kFace,     ///< a face, in its cell colour
};

/// The glyph of the right half of a two-cell (wide) code point in the cell to its left.
inline constexpr char32_t kWideTail = 0;

/// One character cell of the terminal: a code point and its style. A wide
/// code point takes this cell and the next, which holds kWideTail.
struct ScreenCell {
  char32_t glyph = U' ';
  CellStyle style = CellStyle::kPlain;
  TermColour colour;      ///< foreground, for kFace
  TermColour background;  ///< for kFace: a two-colour glyph mode's bg (default: the terminal's)
  bool operator==(const ScreenCell& other) const = default;
};

/// What the terminal should show: the viewer composes a frame, the status
/// line and overlays here, then TerminalWriter sends only what changed.
class ScreenGrid {
 public:
  void Resize(int widthCells, int heightCells);
  int WidthCells() const { return widthCells_; }
  int HeightCells() const { return heightCells_; }
  ScreenCell& At(int col, int row) { return cells_[static_cast<size_t>(row) * widthCells_ + col]; }
  const ScreenCell& At(int col, int row) const {
    return cells_[static_cast<size_t>(row) * widthCells_ + col];
  }
  /// Writes text from (col, row), cut at the right edge; bytes outside
  /// printable ASCII become '?'.
  void Put(int col, int row, std::string_view text, CellStyle style);
  /// The same for code points: one or two cells each, as SafeCodePointCells
  /// gives; the rest (controls, combining, anything beyond ASCII in the C
  /// locale, and a wide one with no room left) become '?'.
  void Put(int col, int row, std::u32string_view text, CellStyle style);
  /// The cells Put takes for text.
  static int CellsOf(std::u32string_view text);
  void FillRow(int row, CellStyle style);
  void Clear();

 private:
  /// Writes one cell; a wide code point it overwrites half of loses its other half (to a blank).
  void Set(int col, int row, const ScreenCell& cell);

  int widthCells_ = 0;
  int heightCells_ = 0;
  std::vector<ScreenCell> cells_;
};

}  // namespace termshade
