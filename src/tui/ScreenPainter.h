#pragma once

#include <optional>
#include <string>
#include <utility>

#include "raster/CellBuffer.h"
#include "shade/CellColour.h"
#include "tui/LineEditor.h"
#include "tui/ScreenGrid.h"

namespace termshade {

/// Composes what the viewer shows into a ScreenGrid: the frame from the one
/// cell buffer, the status line, the prompt and the help overlay. No
/// terminal code here; TerminalWriter sends the grid.
class ScreenPainter {
 public:
  /// The frame's cells, faces coloured by colours (nothing with ColourMode::kNone); a cell
  /// with a background face (the two-colour glyph modes) gets that face's colour as bg.
  /// coarseLevels > 1: colours of that many shades only (CoarseLevel), for a cheap frame.
  void PaintFrame(const CellBuffer& cells, CellColourMap& colours, ScreenGrid& grid,
                  int levelCount = 0, int coarseLevels = 0) const;
  /// The bottom row in reverse video; the text is sanitized and cut to fit.
  void PaintStatus(const std::string& text, ScreenGrid& grid) const;
  /// The bottom row as a text field; returns where the cursor goes (col, row).
  std::pair<int, int> PaintPrompt(const std::string& label, const LineEditor& editor,
                                  ScreenGrid& grid) const;
  void PaintHelp(ScreenGrid& grid) const;
  void PaintTooSmall(ScreenGrid& grid) const;
};

}  // namespace termshade
