#pragma once

#include <string>

#include "io/write/AnsiCells.h"
#include "shade/TerminalTheme.h"

namespace termshade {

/// An asciinema recording (asciicast v2: a JSON header line, then one
/// `[seconds, "o", bytes]` event line per frame) of frames shown one after
/// another at a steady rate, as a terminal of widthCells x heightCells shows
/// them. The first event draws the whole frame; each later one only what
/// changed (AnsiFrameDiff), or the whole frame where that is shorter, and a
/// frame equal to the one before has no event. The header carries the
/// theme, so players and GIF makers (agg) use the colours the frames were
/// made for. No timestamp: the same frames make the same bytes.
class AsciicastRecording {
 public:
  AsciicastRecording(int widthCells, int heightCells, double framesPerSecond,
                     const TerminalTheme& theme = {});

  /// Appends the event that shows one frame (widthCells x heightCells),
  /// preceded by the header for the first frame. The first frame hides the
  /// cursor, clears the screen and draws from the top left.
  void AppendFrame(const AnsiCells& frame, std::string& out);
  /// The closing event, at the last frame's time: the cursor shown again.
  void AppendEnd(std::string& out) const;

 private:
  void AppendHeader(std::string& out) const;

  int widthCells_;
  int heightCells_;
  double framesPerSecond_;
  TerminalTheme theme_;
  long framesWritten_ = 0;
  AnsiCells previous_;  ///< the frame the terminal shows
};

}  // namespace termshade
