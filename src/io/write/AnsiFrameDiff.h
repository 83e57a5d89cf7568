#pragma once

#include <string>

#include "io/write/AnsiCells.h"

namespace termshade {

/// The bytes that turn a terminal showing `previous` into one showing `next`
/// (frames of one size): for each run of cells that look different (glyph,
/// background, and foreground unless blank), a cursor move (CUP) to it and
/// its cells in their colours. Unchanged cells between two changes on a row
/// are sent again where that is no longer (as JSON text: JsonTextLength)
/// than a move. Starts and ends in the terminal's default colours, as a
/// whole frame's rows do, so the screen then looks exactly as `next` drawn
/// whole does (only the invisible foreground of a blank may differ).
/// Nothing when the frames look the same; frames of different sizes: the
/// screen cleared (ED 2), then `next` against blank cells.
void AppendAnsiFrameDiff(const AnsiCells& previous, const AnsiCells& next, std::string& out);

}  // namespace termshade
