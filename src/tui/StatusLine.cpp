#include "tui/StatusLine.h"

#include <algorithm>

namespace termshade {
namespace {

constexpr std::string_view kEllipsis = "...";

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
    if (!kept[i] || minWidth == 0 || segment.text.size() <= minWidth) continue;
    const size_t target =
        std::max(minWidth, segment.text.size() - std::min(overflow, segment.text.size()));
    segment.text = Elide(segment.text, target, segment.elision);
    return true;
  }
  return false;
}

}  // namespace

std::string Elide(const std::string& text, size_t widthCells, Elision elision) {
  if (text.size() <= widthCells) return text;
  if (elision == Elision::kCutEnd) return text.substr(0, widthCells);
  if (widthCells <= kEllipsis.size()) return text.substr(text.size() - widthCells);
  const size_t keep = widthCells - kEllipsis.size();
  const size_t head = elision == Elision::kMiddle ? keep / 4 : 0;
  return text.substr(0, head) + std::string(kEllipsis) + text.substr(text.size() - (keep - head));
}

std::string ComposeStatusLine(std::vector<StatusSegment> segments, int widthCells) {
  const auto width = static_cast<size_t>(std::max(0, widthCells));
  std::vector<bool> kept(segments.size(), true);
  for (;;) {
    const std::string left = Join(segments, kept, false), right = Join(segments, kept, true);
    const size_t gap = left.empty() || right.empty() ? 0 : 1;
    const size_t used = left.size() + gap + right.size();
    if (used <= width) {
      std::string line = left;
      line.append(width - left.size() - right.size(), ' ');
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
