#pragma once

#include <string>
#include <vector>

#include "raster/CellBuffer.h"
#include "tui/LineEditor.h"
#include "tui/TerminalSession.h"

namespace termshade {

/// Puts a cell buffer, the status line and overlays on the ncurses screen.
/// Everything is drawn into ncurses' virtual screen and sent with one
/// doupdate(), so only cells that changed are written to the terminal.
class ScreenPainter {
 public:
  explicit ScreenPainter(const TerminalSession& session) : session_(session) {}

  static int Cols();
  static int Rows();

  void PaintFrame(const CellBuffer& cells, int levelCount, bool colour);
  /// The bottom row, in reverse video; the text is sanitized and cut to fit.
  void PaintStatus(const std::string& text);
  void PaintPrompt(const std::string& label, const LineEditor& editor);
  void PaintHelp();
  void PaintTooSmall();
  void HideCursor();
  void Present();

 private:
  void EnsureColourPairs(int levelCount);

  const TerminalSession& session_;
  int pairsForLevels_ = -1;
  std::vector<unsigned int> rowScratch_;  // chtype per cell of one row (checked in the .cpp)
};

}  // namespace termshade
