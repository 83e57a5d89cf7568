#include "tui/ScreenPainter.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "io/read/LoadError.h"
#include "shade/Utf8.h"
#include "tui/MotionFrames.h"
#include "tui/ViewerKeys.h"

namespace termshade {

void ScreenPainter::PaintFrame(const CellBuffer& cells, CellColourMap& colours, ScreenGrid& grid,
                               int levelCount, int coarseLevels) const {
  const auto shade = [&](int level) { return CoarseLevel(level, levelCount, coarseLevels); };
  const int rows = std::min(cells.HeightCells(), grid.HeightCells());
  const int cols = std::min(cells.WidthCells(), grid.WidthCells());
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < cols; ++col) {
      const int level = cells.Level(col, row);
      ScreenCell& cell = grid.At(col, row);
      cell = {cells.Glyph(col, row), CellStyle::kPlain, TermColour{}, TermColour{}};
      if (level >= 0) {
        cell.style = CellStyle::kFace;
        cell.colour =
            colours.ForFace(cells.FaceNumber(col, row), shade(level), cells.ForeAlbedo(col, row));
        // Two-colour glyph modes (SPEC 11): the samples on the glyph's other side.
        const int backLevel = cells.BackLevel(col, row);
        if (backLevel >= 0)
          cell.background = colours.ForFace(cells.BackFaceNumber(col, row), shade(backLevel),
                                            cells.BackAlbedo(col, row));
        // Both sides in one coarse colour look like a full block of it: sent
        // as one (the writer keeps whatever background it has), and unchanged
        // from the last frame more often.
        if (coarseLevels > 1 && backLevel >= 0 && cell.background == cell.colour) {
          cell.glyph = U'\u2588';
          cell.background = TermColour{};
        }
      }
    }
  }
}

void ScreenPainter::PaintStatus(const std::string& text, ScreenGrid& grid) const {
  const int row = grid.HeightCells() - 1;
  grid.FillRow(row, CellStyle::kReverse);
  // Sanitized text: ASCII, or UTF-8 of one cell per code point (others show as '?').
  if (const auto codePoints = DecodeUtf8(text)) {
    grid.Put(0, row, std::u32string_view(codePoints->data(), codePoints->size()),
             CellStyle::kReverse);
  } else {
    grid.Put(0, row, SanitizeForTerminal(text, 4096), CellStyle::kReverse);
  }
}

std::pair<int, int> ScreenPainter::PaintPrompt(const std::string& label, const LineEditor& editor,
                                               ScreenGrid& grid) const {
  const int row = grid.HeightCells() - 1, width = grid.WidthCells();
  grid.FillRow(row, CellStyle::kPlain);
  grid.Put(0, row, label, CellStyle::kPlain);
  const int fieldStart = static_cast<int>(label.size());
  const int fieldWidth = std::max(1, width - fieldStart - 1);
  // A raw byte of a file name (a control, invalid UTF-8) shows as '?', one cell.
  std::u32string shown = editor.CodePoints();
  for (char32_t& c : shown) c = LineEditor::IsRawByte(c) ? U'?' : c;
  // Scroll the field so the cursor stays visible (wide code points take two cells).
  const size_t cursor = editor.Cursor();
  size_t offset = 0;
  int cursorCells = ScreenGrid::CellsOf(std::u32string_view(shown).substr(0, cursor));
  while (cursorCells > fieldWidth - 1 && offset < cursor) {
    cursorCells -= ScreenGrid::CellsOf(std::u32string_view(shown).substr(offset++, 1));
  }
  grid.Put(fieldStart, row, std::u32string_view(shown).substr(offset), CellStyle::kPlain);
  return {std::min(width - 1, fieldStart + cursorCells), row};
}

void ScreenPainter::PaintHelp(ScreenGrid& grid) const {
  std::vector<std::string> lines{"termshade keys", ""};
  std::istringstream table(FormatViewerKeys(""));
  for (std::string line; std::getline(table, line);) lines.push_back(line);
  lines.insert(lines.end(), {"", "any key closes this help"});
  // A window too short for every row: as many as fit, then where the rest are.
  const auto rowsInside = static_cast<size_t>(std::max(1, grid.HeightCells() - 1 - 2));
  if (lines.size() > rowsInside) {
    lines.resize(rowsInside - 1);
    lines.emplace_back("more: termshade --help; any key closes this");
  }
  size_t longest = 0;
  for (const std::string& line : lines) longest = std::max(longest, line.size());
  const int width = static_cast<int>(longest) + 4, height = static_cast<int>(lines.size()) + 2;
  const int top = std::max(0, (grid.HeightCells() - 1 - height) / 2);
  const int left = std::max(0, (grid.WidthCells() - width) / 2);
  for (int i = 0; i < height && top + i < grid.HeightCells() - 1; ++i) {
    grid.Put(left, top + i, std::string(static_cast<size_t>(width), ' '), CellStyle::kReverse);
    if (i >= 1 && i <= static_cast<int>(lines.size())) {
      grid.Put(left + 2, top + i, lines[static_cast<size_t>(i - 1)], CellStyle::kReverse);
    }
  }
}

void ScreenPainter::PaintTooSmall(ScreenGrid& grid) const {
  grid.Clear();
  grid.Put(0, 0, "terminal too small", CellStyle::kPlain);
}

}  // namespace termshade
