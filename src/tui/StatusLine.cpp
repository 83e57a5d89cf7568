#include "tui/StatusLine.h"

#include <algorithm>

namespace termshade {
namespace {

constexpr std::string_view kEllipsis = "...";

// Sanitized text takes one cell per code point: its bytes but UTF-8 continuation bytes.
size_t Cells(std::string_view text) {
  return static_cast<size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

// The byte offset where cell `cell` starts (the size past the last).
size_t CellOffset(std::string_view text, size_t cell) {
  size_t offset = 0;
  for (size_t seen = 0; offset < text.size(); ++offset) {
    if ((static_cast<unsigned char>(text[offset]) & 0xC0) == 0x80) continue;
    if (seen++ == cell) return offset;
  }
  return text.size();
}

// Cells [first, first + count) of text.
std::string CellRange(const std::string& text, size_t first, size_t count) {
  const size_t start = CellOffset(text, first);
  return text.substr(start, CellOffset(text, first + count) - start);
}

std::string Join(const std::vector<StatusSegment>& segments, const std::vector<bool>& kept,
                 bool right) {
  std::string out;
  for (size_t i = 0; i < segments.size(); ++i) {
    if (!kept[i] || segments[i].rightAligned != right) continue;
    if (!out.empty()) out += " | ";
    out += segments[i].text;
  }
  return out;
}

// Shortens the first shortenable segment still above its minimum by up to
// overflow cells; false when none can give anything.
bool ShortenOne(std::vector<StatusSegment>& segments, const std::vector<bool>& kept,
                size_t overflow) {
  for (size_t i = 0; i < segments.size(); ++i) {
    StatusSegment& segment = segments[i];
    const auto minWidth = static_cast<size_t>(std::max(0, segment.minWidthCells));
    const size_t cells = Cells(segment.text);
    if (!kept[i] || minWidth == 0 || cells <= minWidth) continue;
    const size_t target = std::max(minWidth, cells - std::min(overflow, cells));
    segment.text = Elide(segment.text, target, segment.elision);
    return true;
  }
  return false;
}

}  // namespace

std::string Elide(const std::string& text, size_t widthCells, Elision elision) {
  const size_t cells = Cells(text);
  if (cells <= widthCells) return text;
  if (elision == Elision::kCutEnd) return CellRange(text, 0, widthCells);
  if (widthCells <= kEllipsis.size()) return CellRange(text, cells - widthCells, widthCells);
  const size_t keep = widthCells - kEllipsis.size();
  const size_t head = elision == Elision::kMiddle ? keep / 4 : 0;
  return CellRange(text, 0, head) + std::string(kEllipsis) +
         CellRange(text, cells - (keep - head), keep - head);
}

std::string ComposeStatusLine(std::vector<StatusSegment> segments, int widthCells) {
  const auto width = static_cast<size_t>(std::max(0, widthCells));
  std::vector<bool> kept(segments.size(), true);
  for (;;) {
    const std::string left = Join(segments, kept, false), right = Join(segments, kept, true);
    const size_t gap = left.empty() || right.empty() ? 0 : 1;
    const size_t used = Cells(left) + gap + Cells(right);
    if (used <= width) {
      std::string line = left;
      line.append(width - Cells(left) - Cells(right), ' ');
      line += right;
      return line;
    }
    if (ShortenOne(segments, kept, used - width)) continue;
    // Drop the least important segment still shown, unless it is the last one.
    const auto keptCount = std::count(kept.begin(), kept.end(), true);
    if (keptCount <= 1) {
      const auto last =
          static_cast<size_t>(std::find(kept.begin(), kept.end(), true) - kept.begin());
      return Elide(segments[last].text, width, segments[last].elision);
    }
    int worst = -1;
    for (size_t i = 0; i < segments.size(); ++i) {
      if (kept[i] &&
          (worst < 0 || segments[i].priority > segments[static_cast<size_t>(worst)].priority)) {
        worst = static_cast<int>(i);
      }
    }
    kept[static_cast<size_t>(worst)] = false;
  }
}

}  // namespace termshade
