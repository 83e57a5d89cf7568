#include "tui/ScreenPainter.h"

#include <curses.h>

#include <algorithm>
#include <array>

#include "io/LoadError.h"
#include "shade/Palette.h"

namespace termshade {
namespace {

static_assert(sizeof(chtype) == sizeof(unsigned int), "ScreenPainter keeps chtype as unsigned int");

constexpr short kFirstLevelPair = 1;  // one pair per level, then the background

void PutClipped(int row, int col, const std::string& text, int width) {
  if (width <= 0) return;
  mvaddnstr(row, col, text.c_str(), std::min<int>(width, static_cast<int>(text.size())));
}

}  // namespace

int ScreenPainter::Cols() { return COLS; }
int ScreenPainter::Rows() { return LINES; }

void ScreenPainter::EnsureColourPairs(int levelCount) {
  if (pairsForLevels_ == levelCount || !session_.HasColours()) return;
  pairsForLevels_ = levelCount;
  for (int level = 0; level <= levelCount; ++level) {
    const auto pair = static_cast<short>(kFirstLevelPair + level);
    const bool background = level == levelCount;
    if (session_.Has256Colours()) {
      const auto foreground =
          static_cast<short>(background ? kBackground256 : FaceColour256(level, levelCount));
      init_pair(pair, foreground, static_cast<short>(kBackground256));
    } else {
      init_pair(pair, COLOR_YELLOW, COLOR_CYAN);
    }
  }
}

void ScreenPainter::PaintFrame(const CellBuffer& cells, int levelCount, bool colour) {
  const bool useColour = colour && session_.HasColours();
  if (useColour) EnsureColourPairs(levelCount);
  rowScratch_.resize(static_cast<size_t>(cells.WidthCells()) + 1);
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      chtype ch = static_cast<unsigned char>(cells.Glyph(col, row));
      if (useColour) {
        const int level = cells.Level(col, row);
        const int pairLevel = level < 0 ? levelCount : level;
        ch |= COLOR_PAIR(kFirstLevelPair + pairLevel);
        // Eight colours: brightness from attributes, the glyph still carries the shade.
        if (!session_.Has256Colours() && level >= 0) {
          ch |= level * 3 < levelCount ? A_DIM : (level * 3 >= 2 * levelCount ? A_BOLD : 0);
        }
      }
      rowScratch_[static_cast<size_t>(col)] = ch;
    }
    rowScratch_[static_cast<size_t>(cells.WidthCells())] = 0;
    mvaddchnstr(row, 0, reinterpret_cast<const chtype*>(rowScratch_.data()), cells.WidthCells());
  }
}

void ScreenPainter::PaintStatus(const std::string& text) {
  const int row = LINES - 1, width = COLS;
  attrset(A_REVERSE);
  mvhline(row, 0, ' ', width);
  PutClipped(row, 0, SanitizeForTerminal(text, 4096), width);
  attrset(A_NORMAL);
}

void ScreenPainter::PaintPrompt(const std::string& label, const LineEditor& editor) {
  const int row = LINES - 1, width = COLS;
  attrset(A_NORMAL);
  mvhline(row, 0, ' ', width);
  PutClipped(row, 0, label, width);
  const int fieldStart = static_cast<int>(label.size());
  const int fieldWidth = width - fieldStart - 1;
  if (fieldWidth <= 0) return;
  // Scroll the field so the cursor stays visible.
  const int cursor = static_cast<int>(editor.Cursor());
  const int offset = std::max(0, cursor - fieldWidth + 1);
  PutClipped(row, fieldStart, editor.Text().substr(static_cast<size_t>(offset)), fieldWidth);
  move(row, fieldStart + cursor - offset);
  curs_set(1);
}

void ScreenPainter::PaintHelp() {
  static constexpr std::array<const char*, 21> kLines{
      "termshade keys",
      "",
      "arrows, h j k l  orbit (0.1 rad a press)",
      "+ - PgUp PgDn    closer / farther (x0.5 / x2)",
      "Insert Delete    closer / farther",
      "mouse            drag orbits, wheel: distance",
      "r                reset the view",
      "f                refit the model to the window",
      "m                method: zbuffer painter cull wire",
      "s                shading: contrast / lambert",
      "b                back faces: culled / drawn",
      "c                colour on / off",
      "L                light mode: arrows move the sun",
      "space            turntable on / off",
      "a A              cell aspect - / +",
      "o                open a model file",
      "n p              next / previous model",
      "?                this help",
      "q  Ctrl-C        quit",
      "",
      "any key closes this help"};
  const int width = 50, height = static_cast<int>(kLines.size()) + 2;
  const int top = std::max(0, (LINES - 1 - height) / 2), left = std::max(0, (COLS - width) / 2);
  attrset(A_REVERSE);
  for (int i = 0; i < height && top + i < LINES - 1; ++i) {
    mvhline(top + i, left, ' ', std::min(width, COLS - left));
    if (i >= 1 && i <= static_cast<int>(kLines.size())) {
      PutClipped(top + i, left + 2, kLines[static_cast<size_t>(i - 1)], COLS - left - 2);
    }
  }
  attrset(A_NORMAL);
}

void ScreenPainter::PaintTooSmall() {
  erase();
  PutClipped(0, 0, "terminal too small", COLS);
}

void ScreenPainter::HideCursor() { curs_set(0); }

void ScreenPainter::Present() {
  wnoutrefresh(stdscr);
  doupdate();
}

}  // namespace termshade
