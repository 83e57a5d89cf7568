#include "tui/ScreenGrid.h"

#include <algorithm>
#include <cwchar>

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
      At(col, row) = {c >= 0x20 && c < 0x7f ? static_cast<char32_t>(c) : U'?', style, {}, {}};
    ++col;
  }
}

void ScreenGrid::Put(int col, int row, std::u32string_view text, CellStyle style) {
  if (row < 0 || row >= heightCells_) return;
  for (char32_t c : text) {
    if (col >= widthCells_) break;
    const bool oneCell = c < 0x80 ? c >= 0x20 && c < 0x7f : wcwidth(static_cast<wchar_t>(c)) == 1;
    if (col >= 0) At(col, row) = {oneCell ? c : U'?', style, {}, {}};
    ++col;
  }
}

void ScreenGrid::FillRow(int row, CellStyle style) {
  if (row < 0 || row >= heightCells_) return;
  for (int col = 0; col < widthCells_; ++col) At(col, row) = {U' ', style, {}, {}};
}

void ScreenGrid::Clear() {
  std::fill(cells_.begin(), cells_.end(), ScreenCell{});
}

}  // namespace termshade
