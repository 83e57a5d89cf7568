#include "shade/BlurredGlyphMatch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "shade/BlockGlyphs.h"
#include "shade/GlyphInk.h"

namespace termshade {
namespace {

constexpr int kPx = kInkColumns * kInkRows;

// The block elements a silhouette cell may take besides the mode's patterns:
// lower eighths, left eighths, the right half and the upper and right eighth.
constexpr std::array<char32_t, 19> kBlockElements{
    U'\u2581', U'\u2582', U'\u2583', U'\u2584', U'\u2585', U'\u2586', U'\u2587',
    U'\u2589', U'\u258A', U'\u258B', U'\u258C', U'\u258D', U'\u258E', U'\u258F',
    U'\u2590', U'\u2594', U'\u2595', U'\u2580', U'\u2588'};

// The mode's non-blank patterns, then the block elements, each once.
std::vector<char32_t> Candidates(GlyphMode mode) {
  std::vector<char32_t> glyphs;
  const int count = ModeSampleGrid(mode).Count();
  auto add = [&](char32_t c) {
    if (std::find(glyphs.begin(), glyphs.end(), c) == glyphs.end()) glyphs.push_back(c);
  };
  for (uint32_t p = 1; p < (uint32_t{1} << count); ++p) add(PatternGlyph(mode, p));
  for (char32_t c : kBlockElements) add(c);
  return glyphs;
}

// The blur's weight between pixels dx, dy apart: exp(-d^2 / (4 s^2)), s^2 =
// 4^2 + 1.5^2 (the two blurs), x 1024 rounded; [dx + 7][dy + 15].
using Weights = std::array<std::array<int64_t, 2 * kInkRows>, 2 * kInkColumns>;
Weights BlurWeights() {
  constexpr double kFourVariance = 4.0 * (16.0 + 2.25);
  Weights w{};
  for (int dx = 1 - kInkColumns; dx < kInkColumns; ++dx) {
    for (int dy = 1 - kInkRows; dy < kInkRows; ++dy) {
      w[dx + kInkColumns - 1][dy + kInkRows - 1] =
          std::llround(1024.0 * std::exp(-(dx * dx + dy * dy) / kFourVariance));
    }
  }
  return w;
}

}  // namespace

BlurredGlyphMatch::BlurredGlyphMatch(GlyphMode mode, SampleGrid parts)
    : mode_(mode), parts_(parts), glyphs_(Candidates(mode)) {
  const Weights w = BlurWeights();
  const auto partCount = static_cast<size_t>(parts.Count());
  std::array<size_t, kPx> partOf{};  // the part each pixel's centre lies in
  for (int i = 0; i < kPx; ++i) {
    const int x = i % kInkColumns, y = i / kInkColumns;
    const int row = (2 * y + 1) * parts.down / (2 * kInkRows);
    partOf[i] =
        static_cast<size_t>(row * parts.across + (2 * x + 1) * parts.across / (2 * kInkColumns));
  }
  const InkMap blank{};
  for (char32_t glyph : glyphs_) {
    const InkMap* found = DefaultInkTable().Find(glyph);
    const InkMap& ink = found != nullptr ? *found : blank;
    int64_t self = 0;
    std::vector<int64_t> cross(partCount, 0);
    for (int i = 0; i < kPx; ++i) {
      if (ink[i] == 0) continue;
      for (int j = 0; j < kPx; ++j) {
        const int64_t weight = w[i % kInkColumns - j % kInkColumns + kInkColumns - 1]
                                [i / kInkColumns - j / kInkColumns + kInkRows - 1];
        self += int64_t{ink[i]} * ink[j] * weight;
        cross[partOf[j]] += int64_t{ink[i]} * weight;
      }
    }
    self_.push_back(self);
    cross_.insert(cross_.end(), cross.begin(), cross.end());
  }
}

char32_t BlurredGlyphMatch::Nearest(const uint8_t* values) const {
  const auto partCount = static_cast<size_t>(parts_.Count());
  int64_t best = std::numeric_limits<int64_t>::max();
  char32_t nearest = glyphs_.front();
  // The target's own term is the same for every glyph: left out.
  for (size_t g = 0; g < glyphs_.size(); ++g) {
    int64_t error = self_[g];
    const int64_t* cross = &cross_[g * partCount];
    for (size_t p = 0; p < partCount; ++p) error -= 2 * int64_t{values[p]} * cross[p];
    if (error < best) {
      best = error;
      nearest = glyphs_[g];
    }
  }
  return nearest;
}

}  // namespace termshade
