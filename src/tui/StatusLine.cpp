#include "tui/StatusLine.h"

#include <algorithm>

#include "shade/Utf8.h"

namespace termshade {
namespace {

constexpr std::string_view kEllipsis = "...";

// A code point of sanitized text: where it starts and the cells it takes.
struct Piece {
  size_t offset;
  int cells;
};

std::vector<Piece> Pieces(std::string_view text) {
  std::vector<Piece> pieces;
  for (size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const auto length = std::max<size_t>(1, Utf8SequenceLength(lead));
    int cells = 1;
    if (lead >= 0x80) {
      const auto decoded = DecodeUtf8(text.substr(i, length));
      if (decoded && decoded->size() == 1)
        cells = std::max(1, SafeCodePointCells(decoded->front()));
    }
    pieces.push_back({i, cells});
    i += length;
  }
  return pieces;
}

size_t Cells(std::string_view text) {
  size_t cells = 0;
  for (const Piece& piece : Pieces(text)) cells += static_cast<size_t>(piece.cells);
  return cells;
}

// The longest start (or end) of text within widthCells.
std::string Front(const std::string& text, const std::vector<Piece>& pieces, size_t widthCells) {
  size_t used = 0, count = 0;
  while (count < pieces.size() && used + pieces[count].cells <= widthCells)
    used += pieces[count++].cells;
  return text.substr(0, count < pieces.size() ? pieces[count].offset : text.size());
}
std::string Back(const std::string& text, const std::vector<Piece>& pieces, size_t widthCells) {
  size_t used = 0, first = pieces.size();
  while (first > 0 && used + pieces[first - 1].cells <= widthCells) used += pieces[--first].cells;
  return text.substr(first < pieces.size() ? pieces[first].offset : text.size());
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
  const std::vector<Piece> pieces = Pieces(text);
  if (Cells(text) <= widthCells) return text;
  if (elision == Elision::kCutEnd) return Front(text, pieces, widthCells);
  if (widthCells <= kEllipsis.size()) return Back(text, pieces, widthCells);
  const size_t keep = widthCells - kEllipsis.size();
  const std::string head = Front(text, pieces, elision == Elision::kMiddle ? keep / 4 : 0);
  return head + std::string(kEllipsis) + Back(text, pieces, keep - Cells(head));
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
