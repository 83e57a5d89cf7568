#include "io/write/AsciicastRecording.h"

#include <cstdio>

#include "io/write/AnsiFrameDiff.h"
#include "io/write/JsonText.h"

namespace termshade {
namespace {

void AppendSeconds(double seconds, std::string& out) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", seconds);
  out += text;
}

// The frame's ansi rows joined by CR LF, none after the last.
void AppendWholeFrame(const AnsiCells& frame, std::string& out) {
  std::string ansi;
  AppendAnsiRows(frame, ansi);
  std::string_view rest = ansi;
  while (!rest.empty()) {
    const size_t end = rest.find('\n');
    out += rest.substr(0, end);
    if (end == std::string_view::npos || end + 1 == rest.size()) break;
    out += "\r\n";
    rest.remove_prefix(end + 1);
  }
}

}  // namespace

AsciicastRecording::AsciicastRecording(int widthCells, int heightCells, double framesPerSecond,
                                       const TerminalTheme& theme)
    : widthCells_(widthCells),
      heightCells_(heightCells),
      framesPerSecond_(framesPerSecond),
      theme_(theme) {}

void AsciicastRecording::AppendHeader(std::string& out) const {
  out += "{\"version\": 2, \"width\": " + std::to_string(widthCells_) +
         ", \"height\": " + std::to_string(heightCells_) + ", \"theme\": {\"fg\": \"" +
         HexColour(theme_.foreground) + "\", \"bg\": \"" + HexColour(theme_.background) +
         "\", \"palette\": \"";
  for (size_t i = 0; i < theme_.palette.size(); ++i) {
    if (i > 0) out += ':';
    out += HexColour(theme_.palette[i]);
  }
  out += "\"}, \"env\": {\"TERM\": \"xterm-256color\"}}\n";
}

void AsciicastRecording::AppendFrame(const AnsiCells& frame, std::string& out) {
  // Step 1: the header, before the first frame.
  std::string bytes;
  const bool sameSize = previous_.WidthCells() == frame.WidthCells() &&
                        previous_.HeightCells() == frame.HeightCells();
  if (framesWritten_ == 0) {
    AppendHeader(out);
    bytes = "\x1b[?25l\x1b[2J";
  } else if (!sameSize) {
    bytes = "\x1b[2J";  // a frame of another size: nothing of the last may stay
  }
  // Step 2: the whole frame from the top left, rows joined by CR LF; no line
  // feed after the last row, so a terminal of the frame's height never scrolls.
  bytes += "\x1b[H";
  AppendWholeFrame(frame, bytes);
  // Step 3: after the first, only what changed, where that is shorter; an
  // unchanged frame has no event (the next one keeps its own time).
  if (framesWritten_ > 0 && sameSize) {
    std::string changes;
    AppendAnsiFrameDiff(previous_, frame, changes);
    if (JsonTextLength(changes) < JsonTextLength(bytes)) bytes = std::move(changes);
  }
  previous_ = frame;
  // Step 4: the event, at the frame's time.
  if (!bytes.empty()) {
    out += '[';
    AppendSeconds(static_cast<double>(framesWritten_) / framesPerSecond_, out);
    out += ", \"o\", ";
    AppendJsonText(bytes, out);
    out += "]\n";
  }
  ++framesWritten_;
}

void AsciicastRecording::AppendEnd(std::string& out) const {
  if (framesWritten_ == 0) return;
  out += '[';
  AppendSeconds(static_cast<double>(framesWritten_ - 1) / framesPerSecond_, out);
  out += ", \"o\", ";
  AppendJsonText("\x1b[?25h", out);
  out += "]\n";
}

}  // namespace termshade
