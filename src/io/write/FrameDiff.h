#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace termshade {

/// Two text frames side by side, golden left and actual right, showing only
/// the rows with a marked cell and one row either side ("..." between
/// groups). Marked cells are shown in reverse red with colour, else a row of
/// `^` under each marked row. A control or format character (IsControlOrFormat)
/// is shown as `?`: a golden is a file from anywhere, and no escape sequence
/// of it reaches a terminal.
/// `marked` has one entry a cell, row-major, widthCells x goldenRows.size().
std::string SideBySideFrameDiff(const std::vector<std::string>& goldenRows,
                                const std::vector<std::string>& actualRows,
                                const std::vector<uint8_t>& marked, int widthCells, bool colour);

/// Two text frames (rows ended by '\n') compared cell by cell, as the
/// project's own golden frames are.
struct TextFrameDifference {
  int differingCells = 0;  ///< cells whose character differs (rows missing: every cell)
  bool sameShape = true;   ///< the same number of rows of the same widths
  std::string diff;        ///< SideBySideFrameDiff of the two, empty when equal
};

/// Exact comparison of two text frames, with the readable diff users see.
TextFrameDifference CompareTextFrames(std::string_view golden, std::string_view actual,
                                      bool colour);

}  // namespace termshade
