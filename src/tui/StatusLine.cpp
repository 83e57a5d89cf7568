#include "tui/StatusLine.h"

#include <algorithm>

namespace termshade {
namespace {

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

}  // namespace

std::string ComposeStatusLine(const std::vector<StatusSegment>& segments, int widthCells) {
  const auto width = static_cast<size_t>(std::max(0, widthCells));
  std::vector<bool> kept(segments.size(), true);
  for (;;) {
    const std::string left = Join(segments, kept, false), right = Join(segments, kept, true);
    const size_t gap = left.empty() || right.empty() ? 0 : 1;
    if (left.size() + gap + right.size() <= width) {
      std::string line = left;
      line.append(width - left.size() - right.size(), ' ');
      line += right;
      return line;
    }
    // Drop the least important segment still shown, unless it is the last one.
    int worst = -1;
    for (size_t i = 0; i < segments.size(); ++i) {
      if (kept[i] &&
          (worst < 0 || segments[i].priority > segments[static_cast<size_t>(worst)].priority)) {
        worst = static_cast<int>(i);
      }
    }
    if (std::count(kept.begin(), kept.end(), true) <= 1) return (left + right).substr(0, width);
    kept[static_cast<size_t>(worst)] = false;
  }
}

}  // namespace termshade
