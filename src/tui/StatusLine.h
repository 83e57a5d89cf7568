#pragma once

#include <string>
#include <vector>

namespace termshade {

/// A piece of the status line; lower priority numbers are kept longest.
struct StatusSegment {
  std::string text;
  int priority = 0;
  bool rightAligned = false;
};

/// Lays the segments out in one row of widthCells: left segments joined by
/// " | " from the left, right ones flush right; segments are dropped from the
/// highest priority number down until the rest fit, and the last one left is
/// cut if it alone is too wide. Text must already be sanitized.
std::string ComposeStatusLine(const std::vector<StatusSegment>& segments, int widthCells);

}  // namespace termshade
