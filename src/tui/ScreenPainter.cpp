#include "tui/ScreenPainter.h"

#include <algorithm>
#include <array>

#include "io/LoadError.h"

namespace termshade {

void ScreenPainter::PaintFrame(const CellBuffer& cells, ScreenGrid& grid) const {
  const int rows = std::min(cells.HeightCells(), grid.HeightCells());
  const int cols = std::min(cells.WidthCells(), grid.WidthCells());
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < cols; ++col) {
      const int level = cells.Level(col, row);
      grid.At(col, row) = {cells.Glyph(col, row),
                           level < 0 ? CellStyle::kBackground : CellStyle::kFace,
                           static_cast<int8_t>(std::max(0, level))};
    }
  }
}

void ScreenPainter::PaintStatus(const std::string& text, ScreenGrid& grid) const {
  const int row = grid.HeightCells() - 1;
  grid.FillRow(row, CellStyle::kReverse);
  grid.Put(0, row, SanitizeForTerminal(text, 4096), CellStyle::kReverse);
}

std::pair<int, int> ScreenPainter::PaintPrompt(const std::string& label, const LineEditor& editor,
                                               ScreenGrid& grid) const {
  const int row = grid.HeightCells() - 1, width = grid.WidthCells();
  grid.FillRow(row, CellStyle::kPlain);
  grid.Put(0, row, label, CellStyle::kPlain);
  const int fieldStart = static_cast<int>(label.size());
  const int fieldWidth = std::max(1, width - fieldStart - 1);
  // Scroll the field so the cursor stays visible.
  const int cursor = static_cast<int>(editor.Cursor());
  const int offset = std::max(0, cursor - fieldWidth + 1);
  grid.Put(fieldStart, row,
           std::u32string_view(editor.CodePoints()).substr(static_cast<size_t>(offset)),
           CellStyle::kPlain);
  return {std::min(width - 1, fieldStart + cursor - offset), row};
}

void ScreenPainter::PaintHelp(ScreenGrid& grid) const {
  static constexpr std::array<const char*, 22> kLines{
      "termshade keys",
      "",
      "arrows, h j k l  orbit (0.1 rad a press)",
      "+ - PgUp PgDn    closer / farther (x0.5 / x2)",
      "Insert Delete    closer / farther",
      "mouse            drag orbits, wheel: distance",
      "r                reset the view",
      "f                refit the model to the window",
      "m                method: zbuffer painter cull wire auto",
      "s                shading: contrast / lambert",
      "b                back faces: culled / drawn",
      "c                colour on / off",
      "g                glyphs: ramp ascii blocks ...",
      "L                light mode: arrows move the sun",
      "space            turntable on / off",
      "a A              cell aspect - / +",
      "o                open a model file (Tab completes)",
      "n p              next / previous model",
      "?                this help",
      "q  Ctrl-C        quit (Ctrl-Z suspends)",
      "",
      "any key closes this help"};
  const int width = 50, height = static_cast<int>(kLines.size()) + 2;
  const int top = std::max(0, (grid.HeightCells() - 1 - height) / 2);
  const int left = std::max(0, (grid.WidthCells() - width) / 2);
  for (int i = 0; i < height && top + i < grid.HeightCells() - 1; ++i) {
    grid.Put(left, top + i, std::string(static_cast<size_t>(width), ' '), CellStyle::kReverse);
    if (i >= 1 && i <= static_cast<int>(kLines.size())) {
      grid.Put(left + 2, top + i, kLines[static_cast<size_t>(i - 1)], CellStyle::kReverse);
    }
  }
}

void ScreenPainter::PaintTooSmall(ScreenGrid& grid) const {
  grid.Clear();
  grid.Put(0, 0, "terminal too small", CellStyle::kPlain);
}

}  // namespace termshade
