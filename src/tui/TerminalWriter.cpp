#include "tui/TerminalWriter.h"

#include <curses.h>
#include <term.h>
#include <unistd.h>

#include <cerrno>

#include "io/write/FrameFormats.h"
#include "shade/Utf8.h"

namespace termshade {
namespace {

// A terminfo string capability, or "" when the terminal lacks it.
const char* Capability(const char* name) {
  char* value = tigetstr(name);
  // tigetstr's documented "not a string capability" value is (char*)-1.
  return value == nullptr || value == reinterpret_cast<char*>(-1) ? "" : value;  // NOLINT
}

// Appends a terminfo string without its padding ("$<5>", "$<2*/>"): delays
// for hardware terminals, which tputs would turn into time or NUL bytes and
// which no terminal emulator needs.
void AppendWithoutPadding(std::string& out, const char* text) {
  for (const char* p = text; *p != '\0'; ++p) {
    if (p[0] == '$' && p[1] == '<') {
      const char* q = p + 2;
      while ((*q >= '0' && *q <= '9') || *q == '.' || *q == '*' || *q == '/') ++q;
      if (*q == '>' && q > p + 2) {
        p = q;
        continue;
      }
    }
    out += *p;
  }
}

void AppendCapability(std::string& out, const char* name) {
  AppendWithoutPadding(out, Capability(name));
}

void AppendParameterized(std::string& out, const char* name, int a) {
  const char* format = Capability(name);
  if (*format != '\0') AppendWithoutPadding(out, tiparm(format, a));
}

}  // namespace

void TerminalWriter::AppendMove(int col, int row) {
  const char* cup = Capability("cup");
  if (*cup != '\0') AppendWithoutPadding(out_, tiparm(cup, row, col));
}

TerminalWriter::Attributes TerminalWriter::AttributesFor(const ScreenCell& cell) {
  Attributes a;
  a.reverse = cell.style == CellStyle::kReverse;
  if (cell.style == CellStyle::kFace) {
    a.foreground = cell.colour;
    a.background = cell.background;
  }
  return a;
}

void TerminalWriter::AppendAttributes(const Attributes& wanted) {
  if (wanted == current_) return;
  // SGR can only add attributes; dropping one (or a colour) means a reset first.
  const auto dropped = [](const TermColour& now, const TermColour& next) {
    return now.kind != TermColour::Kind::kDefault && next.kind == TermColour::Kind::kDefault;
  };
  const bool reset = (current_.reverse && !wanted.reverse) ||
                     dropped(current_.foreground, wanted.foreground) ||
                     dropped(current_.background, wanted.background);
  if (reset) {
    AppendCapability(out_, "sgr0");
    current_ = Attributes{};
  }
  if (wanted.reverse && !current_.reverse) AppendCapability(out_, "rev");
  if (!(wanted.foreground == current_.foreground)) {
    if (wanted.foreground.kind == TermColour::Kind::kIndexed && wanted.foreground.index >= 16) {
      AppendParameterized(out_, "setaf", wanted.foreground.index);
    } else if (wanted.foreground.kind != TermColour::Kind::kDefault) {
      // 24-bit colour has no terminfo string; the 16 ANSI colours are SGR
      // 30-37 and 90-97 (an 8-colour entry's setaf cannot give 8-15).
      AppendForegroundSgr(wanted.foreground, out_);
    }
  }
  if (!(wanted.background == current_.background)) {
    if (wanted.background.kind == TermColour::Kind::kIndexed && wanted.background.index >= 16) {
      AppendParameterized(out_, "setab", wanted.background.index);
    } else if (wanted.background.kind != TermColour::Kind::kDefault) {
      AppendBackgroundSgr(wanted.background, out_);
    }
  }
  current_ = wanted;
}

void TerminalWriter::Present(const ScreenGrid& grid, std::optional<std::pair<int, int>> cursor,
                             std::string_view trailer) {
  out_.clear();
  const bool full = !valid_ || previous_.WidthCells() != grid.WidthCells() ||
                    previous_.HeightCells() != grid.HeightCells();
  if (cursorShown_) {
    AppendCapability(out_, "civis");
    cursorShown_ = false;
  }
  if (full) {
    // Clear the screen to the terminal's own background; blank cells need
    // not be sent again.
    AppendCapability(out_, "sgr0");
    current_ = Attributes{};
    const ScreenCell cleared;
    AppendCapability(out_, "clear");
    previous_.Resize(grid.WidthCells(), grid.HeightCells());
    for (int row = 0; row < grid.HeightCells(); ++row) {
      for (int col = 0; col < grid.WidthCells(); ++col) previous_.At(col, row) = cleared;
    }
  }
  // Step 1: runs of changed cells; a gap of a few unchanged cells is
  // re-sent rather than paid for with a cursor move.
  int cursorCol = -1, cursorRow = -1;
  constexpr int kMaxGap = 4;
  const bool avoidLastCell = !BottomRightWritable();
  for (int row = 0; row < grid.HeightCells(); ++row) {
    int col = 0;
    const int rowEnd =
        avoidLastCell && row == grid.HeightCells() - 1 ? grid.WidthCells() - 1 : grid.WidthCells();
    while (col < rowEnd) {
      const bool changed = !(grid.At(col, row) == previous_.At(col, row));
      if (!changed) {
        ++col;
        continue;
      }
      int end = col + 1;  // extend over changed cells and short unchanged gaps
      for (int gap = 0; end < rowEnd && gap <= kMaxGap; ++end) {
        const bool next = !(grid.At(end, row) == previous_.At(end, row));
        gap = next ? 0 : gap + 1;
        if (gap > kMaxGap) {
          end -= kMaxGap;
          break;
        }
      }
      // A wide code point is sent whole: from its first cell, through its tail.
      if (col > 0 && grid.At(col, row).glyph == kWideTail) --col;
      if (end < rowEnd && grid.At(end, row).glyph == kWideTail) ++end;
      if (cursorRow != row || cursorCol != col) AppendMove(col, row);
      for (int c = col; c < end; ++c) {
        const ScreenCell& cell = grid.At(c, row);
        Attributes wanted = AttributesFor(cell);
        // A full block hides its background: keep the current one rather than pay for a reset.
        if (cell.glyph == U'\u2588') wanted.background = current_.background;
        AppendAttributes(wanted);
        // A lone tail shows blank, as does a lead whose tail is in a last cell kept blank.
        const bool lead = cell.glyph != kWideTail && c + 1 < grid.WidthCells() &&
                          grid.At(c + 1, row).glyph == kWideTail;
        const bool whole = lead && c + 1 < end;
        AppendUtf8(out_, cell.glyph == kWideTail || (lead && !whole) ? U' ' : cell.glyph);
        if (whole) ++c;  // the terminal moved two cells
      }
      cursorCol = end;
      cursorRow = row;
      col = end;
    }
  }
  // Step 2: the cursor, shown only where text is being typed.
  if (cursor) {
    AppendMove(cursor->first, cursor->second);
    AppendCapability(out_, "cnorm");
    cursorShown_ = true;
  }
  out_ += trailer;
  WriteAll();
  previous_ = grid;
  valid_ = true;
}

void TerminalWriter::Send(std::string_view bytes) {
  out_.assign(bytes);
  WriteAll();
}

bool TerminalWriter::BottomRightWritable() {
  return tigetflag("am") != 1 || tigetflag("xenl") == 1;
}

TerminalWriter::~TerminalWriter() {
  Release();
}

void TerminalWriter::Release() {
  out_.clear();
  AppendCapability(out_, "sgr0");
  AppendCapability(out_, "cnorm");
  WriteAll();
  current_ = Attributes{};
  cursorShown_ = true;
}

std::string TerminalWriter::ResetSequence() {
  // Mouse reports off in every protocol ncurses may have asked for (X10,
  // button-event, any-event, SGR 1006); no terminfo string undoes them all.
  std::string out = "\x1b[?1000l\x1b[?1002l\x1b[?1003l\x1b[?1006l";
  AppendCapability(out, "sgr0");
  AppendCapability(out, "cnorm");
  AppendCapability(out, "rmkx");
  AppendCapability(out, "rmcup");
  // Without an alternate screen the last frame would stay among the shell's lines.
  if (*Capability("rmcup") == '\0') AppendCapability(out, "clear");
  return out;
}

void TerminalWriter::WriteAll() {
  lastFrameBytes_ = out_.size();
  if (sink_ != nullptr) {
    sink_->append(out_);
    return;
  }
  size_t sent = 0;
  while (sent < out_.size()) {
    const ssize_t n = write(outputFd_, out_.data() + sent, out_.size() - sent);
    if (n > 0) {
      sent += static_cast<size_t>(n);
    } else if (n < 0 && errno != EINTR && errno != EAGAIN) {
      return;  // the terminal is gone; the event loop will notice on input
    }
  }
}

}  // namespace termshade
