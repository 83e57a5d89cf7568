#include "tui/ScreenGrid.h"

#include <algorithm>

#include "shade/Utf8.h"

namespace termshade {

void ScreenGrid::Resize(int widthCells, int heightCells) {
  widthCells_ = std::max(0, widthCells);
  heightCells_ = std::max(0, heightCells);
  cells_.assign(static_cast<size_t>(widthCells_) * heightCells_, ScreenCell{});
}

void ScreenGrid::Put(int col, int row, std::string_view text, CellStyle style) {
  if (row < 0 || row >= heightCells_) return;
  for (char c : text) {
    if (col >= widthCells_) break;
    if (col >= 0)
      Set(col, row, {c >= 0x20 && c < 0x7f ? static_cast<char32_t>(c) : U'?', style, {}, {}});
    ++col;
  }
}

namespace {

// Cells a code point takes on the screen; 1 for one shown as '?'.
int CellsFor(char32_t c) {
  if (c < 0x80) return 1;
  return std::max(1, SafeCodePointCells(c));
}

}  // namespace

void ScreenGrid::Put(int col, int row, std::u32string_view text, CellStyle style) {
  if (row < 0 || row >= heightCells_) return;
  for (char32_t c : text) {
    if (col >= widthCells_) break;
    const int cells = c < 0x80 ? (c >= 0x20 && c < 0x7f ? 1 : 0) : SafeCodePointCells(c);
    if (cells == 2 && col >= 0 && col + 1 < widthCells_) {
      Set(col, row, {c, style, {}, {}});
      Set(col + 1, row, {kWideTail, style, {}, {}});
      col += 2;
      continue;
    }
    if (col >= 0) Set(col, row, {cells == 1 ? c : U'?', style, {}, {}});
    ++col;
  }
}

int ScreenGrid::CellsOf(std::u32string_view text) {
  int cells = 0;
  for (char32_t c : text) cells += CellsFor(c);
  return cells;
}

void ScreenGrid::Set(int col, int row, const ScreenCell& cell) {
  ScreenCell& at = At(col, row);
  if (at.glyph == kWideTail && cell.glyph != kWideTail && col > 0) At(col - 1, row).glyph = U' ';
  if (at.glyph != kWideTail && col + 1 < widthCells_ && At(col + 1, row).glyph == kWideTail) {
    At(col + 1, row).glyph = U' ';
  }
  at = cell;
}

void ScreenGrid::FillRow(int row, CellStyle style) {
  if (row < 0 || row >= heightCells_) return;
  for (int col = 0; col < widthCells_; ++col) At(col, row) = {U' ', style, {}, {}};
}

void ScreenGrid::Clear() {
  std::fill(cells_.begin(), cells_.end(), ScreenCell{});
}

}  // namespace termshade
