#include "io/write/AnsiFrameDiff.h"

#include "io/write/FrameFormats.h"
#include "io/write/JsonText.h"
#include "shade/Utf8.h"

namespace termshade {
namespace {

// The colours the terminal draws the next glyph in.
struct Pen {
  TermColour foreground;
  TermColour background;
  bool operator==(const Pen&) const = default;
};

// A blank shows no foreground: whatever the pen has will do.
bool Blank(const AnsiCell& cell) {
  return cell.glyph == U' ';
}

// One SGR of both planes: "\x1b[38;5;1m" and "\x1b[48;5;2m" as "\x1b[38;5;1;48;5;2m".
void AppendBothSgr(const Pen& wanted, std::string& out) {
  std::string foreground, background;
  AppendForegroundSgr(wanted.foreground, foreground);
  AppendBackgroundSgr(wanted.background, background);
  foreground.back() = ';';
  out += foreground;
  out.append(background, 2);
}

// SGR that changes the pen to the cell's colours; a reset where both become
// the terminal's (or a blank's background does).
void AppendPen(const AnsiCell& cell, Pen& pen, std::string& out) {
  Pen wanted{Blank(cell) ? pen.foreground : cell.foreground, cell.background};
  if (wanted == pen) return;
  if (Blank(cell) && wanted.background == TermColour{}) wanted.foreground = {};
  const bool foreground = !(wanted.foreground == pen.foreground);
  const bool background = !(wanted.background == pen.background);
  if (wanted == Pen{}) {
    out += "\x1b[0m";
  } else if (foreground && background) {
    AppendBothSgr(wanted, out);
  } else if (foreground) {
    AppendForegroundSgr(wanted.foreground, out);
  } else {
    AppendBackgroundSgr(wanted.background, out);
  }
  pen = wanted;
}

// CUP: rows and columns counted from 1.
void AppendMove(int col, int row, std::string& out) {
  out += "\x1b[";
  out += std::to_string(row + 1);
  out += ';';
  out += std::to_string(col + 1);
  out += 'H';
}

// Cells [from, to) of a row, each in its colours.
void AppendCells(const AnsiCells& cells, int row, int from, int to, Pen& pen, std::string& out) {
  for (int col = from; col < to; ++col) {
    const AnsiCell& cell = cells.At(col, row);
    AppendPen(cell, pen, out);
    AppendUtf8(out, cell.glyph);
  }
}

// Whether two cells look the same: glyph and background, and the foreground
// unless both are blank.
bool LookAlike(const AnsiCell& a, const AnsiCell& b) {
  return a.glyph == b.glyph && a.background == b.background &&
         (Blank(a) || a.foreground == b.foreground);
}

// The first cell of the row at or after col that looks different, or the row's width.
int NextChange(const AnsiCells& previous, const AnsiCells& next, int row, int col) {
  while (col < next.WidthCells() && LookAlike(previous.At(col, row), next.At(col, row))) ++col;
  return col;
}

// A cursor move costs at most 12 bytes and a pen change a 36-byte SGR (as
// JSON text, 17 and 41): a longer gap, at least a byte a cell, never costs
// less to send again.
constexpr int kLongestGapCells = 64;

// Whether sending the unchanged cells [from, to) and the changed cell at `to`
// is no longer than moving to `to` and sending that cell.
bool GapCheaper(const AnsiCells& cells, int row, int from, int to, const Pen& pen) {
  if (to - from > kLongestGapCells) return false;
  std::string through, jump;
  Pen throughPen = pen, jumpPen = pen;
  AppendCells(cells, row, from, to + 1, throughPen, through);
  AppendMove(to, row, jump);
  AppendCells(cells, row, to, to + 1, jumpPen, jump);
  return JsonTextLength(through) <= JsonTextLength(jump);
}

// The changes of one row, left to right.
void AppendRowChanges(const AnsiCells& previous, const AnsiCells& next, int row, Pen& pen,
                      std::string& out) {
  const int width = next.WidthCells();
  int col = NextChange(previous, next, row, 0);
  bool cursorThere = false;
  while (col < width) {
    if (!cursorThere) AppendMove(col, row, out);
    AppendCells(next, row, col, col + 1, pen, out);
    const int following = NextChange(previous, next, row, col + 1);
    if (following == width) return;
    cursorThere = GapCheaper(next, row, col + 1, following, pen);
    if (cursorThere) AppendCells(next, row, col + 1, following, pen, out);
    col = following;
  }
}

}  // namespace

void AppendAnsiFrameDiff(const AnsiCells& previous, const AnsiCells& next, std::string& out) {
  if (previous.WidthCells() != next.WidthCells() || previous.HeightCells() != next.HeightCells()) {
    // Another size: the screen cleared, then every cell that is not blank.
    AnsiCells cleared;
    cleared.Resize(next.WidthCells(), next.HeightCells());
    out += "\x1b[2J";
    return AppendAnsiFrameDiff(cleared, next, out);
  }
  Pen pen;
  for (int row = 0; row < next.HeightCells(); ++row)
    AppendRowChanges(previous, next, row, pen, out);
  if (!(pen == Pen{})) out += "\x1b[0m";
}

}  // namespace termshade
