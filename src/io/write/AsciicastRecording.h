#pragma once

#include <string>
#include <string_view>

#include "shade/TerminalTheme.h"

namespace termshade {

/// An asciinema recording (asciicast v2: a JSON header line, then one
/// `[seconds, "o", bytes]` event line per frame) of frames shown one after
/// another at a steady rate, as a terminal of widthCells x heightCells shows
/// them. The header carries the theme, so players and GIF makers (agg) use
/// the colours the frames were made for. No timestamp: the same frames make
/// the same bytes.
class AsciicastRecording {
 public:
  AsciicastRecording(int widthCells, int heightCells, double framesPerSecond,
                     const TerminalTheme& theme = {});

  /// Appends the event that shows one frame (its ansi dump: rows ended by
  /// '\n'), preceded by the header for the first frame. The first frame
  /// hides the cursor and clears the screen; each draws from the top left.
  void AppendFrame(std::string_view ansiFrame, std::string& out);
  /// The closing event, at the last frame's time: the cursor shown again.
  void AppendEnd(std::string& out) const;

 private:
  int widthCells_;
  int heightCells_;
  double framesPerSecond_;
  TerminalTheme theme_;
  long framesWritten_ = 0;
};

/// text as a JSON string (quotes, backslashes and control bytes escaped;
/// UTF-8 passed through).
void AppendJsonText(std::string_view text, std::string& out);

}  // namespace termshade
