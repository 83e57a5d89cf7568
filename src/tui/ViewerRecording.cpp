#include "tui/ViewerRecording.h"

#include <cstdio>

#include "io/write/AsciicastRecording.h"
#include "io/write/JsonText.h"

namespace termshade {
namespace {

// Bytes gathered before a write to the file.
constexpr size_t kFlushBytes = 1 << 16;
// Bytes of events held for the header's theme at most (a few seconds of big
// frames); past them the header takes the theme known so far.
constexpr size_t kMaxHeldBytes = 4 << 20;

}  // namespace

std::optional<std::string> ViewerRecording::Open(const TerminalTheme& theme) {
  theme_ = theme;
  error_ = file_.Open();
  return error_;
}

void ViewerRecording::AppendEvent(double seconds, char type, std::string_view text) {
  char time[32];
  std::snprintf(time, sizeof time, "[%.6f, \"%c\", ", seconds, type);
  pending_ += time;
  AppendJsonText(text, pending_);
  pending_ += "]\n";
}

void ViewerRecording::Frame(const ScreenGrid& grid, std::optional<std::pair<int, int>> cursor,
                            Clock::time_point now) {
  if (error_) return;
  // Step 1: the start, at the first frame: the header's size (its theme may come later).
  if (!start_) {
    start_ = now;
    widthCells_ = headerWidthCells_ = grid.WidthCells();
    heightCells_ = headerHeightCells_ = grid.HeightCells();
  }
  const double seconds = std::chrono::duration<double>(now - *start_).count();
  // Step 2: a resize, as players take it; the writer repaints the whole screen.
  if (grid.WidthCells() != widthCells_ || grid.HeightCells() != heightCells_) {
    widthCells_ = grid.WidthCells();
    heightCells_ = grid.HeightCells();
    AppendEvent(seconds, 'r', std::to_string(widthCells_) + "x" + std::to_string(heightCells_));
  }
  // Step 3: what changed, as the terminal would be sent it.
  bytes_.clear();
  writer_.Present(grid, cursor);
  if (!bytes_.empty()) AppendEvent(seconds, 'o', bytes_);
  if (pending_.size() >= kFlushBytes) Flush();
}

void ViewerRecording::SettleTheme(const TerminalTheme& theme) {
  if (headerWritten_) return;
  theme_ = theme;
  themeSettled_ = true;
  Flush();
}

std::string ViewerRecording::Header() const {
  std::string header = "{\"version\": 2, \"width\": " + std::to_string(headerWidthCells_) +
                       ", \"height\": " + std::to_string(headerHeightCells_) +
                       ", \"theme\": {\"fg\": \"" + HexColour(theme_.foreground) +
                       "\", \"bg\": \"" + HexColour(theme_.background) + "\", \"palette\": \"";
  for (size_t i = 0; i < theme_.palette.size(); ++i) {
    if (i > 0) header += ':';
    header += HexColour(theme_.palette[i]);
  }
  return header + "\"}, \"env\": {\"TERM\": \"xterm-256color\"}}\n";
}

// The events go out after the header, which waits for its theme (up to kMaxHeldBytes).
void ViewerRecording::Flush() {
  if (!headerWritten_ && start_) {
    if (!themeSettled_ && pending_.size() < kMaxHeldBytes) return;
    pending_.insert(0, Header());
    headerWritten_ = true;
  }
  if (!error_ && !pending_.empty()) error_ = file_.Write(pending_);
  pending_.clear();
}

std::optional<std::string> ViewerRecording::Finish(Clock::time_point now) {
  if (!error_ && start_) {
    bytes_.clear();
    writer_.Release();
    AppendEvent(std::chrono::duration<double>(now - *start_).count(), 'o', bytes_);
  }
  themeSettled_ = true;  // no answer now: the theme as it is
  Flush();
  if (!error_) error_ = file_.Commit();
  return error_;
}

}  // namespace termshade
