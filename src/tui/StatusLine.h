#pragma once

#include <string>
#include <vector>

namespace termshade {

/// Where a too-long segment loses characters: its end, its front (a path
/// keeps its file name) or its middle (a message keeps its first word too).
enum class Elision { kCutEnd, kFront, kMiddle };

/// A piece of the status line; lower priority numbers are kept longest.
struct StatusSegment {
  std::string text;
  int priority = 0;
  bool rightAligned = false;
  Elision elision = Elision::kCutEnd;
  /// Nonzero: the segment is shortened (by its elision) down to this many
  /// cells before any other segment is dropped.
  int minWidthCells = 0;
};

/// Lays the segments out in one row of widthCells: left segments joined by
/// " | " from the left, right ones flush right. When they do not fit, a
/// segment with a minimum width is shortened first, then segments are
/// dropped from the highest priority number down, and the last one left is
/// elided to the width. Text must already be sanitized (SanitizeForTerminal:
/// ASCII, or UTF-8 of one cell per code point).
std::string ComposeStatusLine(std::vector<StatusSegment> segments, int widthCells);

/// text in at most widthCells cells (code points), "..." marking where it was cut.
std::string Elide(const std::string& text, size_t widthCells, Elision elision);

}  // namespace termshade
