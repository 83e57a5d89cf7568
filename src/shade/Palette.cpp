#include "shade/Palette.h"

#include <algorithm>
#include <array>

namespace termshade {

int FaceColour256(int level, int levelCount) {
  // Colour cube entries 16 + 36r + 6g + b from dark olive to pale yellow.
  static constexpr std::array<int, 10> kYellows{58, 100, 142, 184, 220, 226, 227, 228, 229, 230};
  if (levelCount <= 1) return kYellows.back();
  const int last = static_cast<int>(kYellows.size()) - 1;
  const int index =
      (std::clamp(level, 0, levelCount - 1) * last + (levelCount - 1) / 2) / (levelCount - 1);
  return kYellows[static_cast<size_t>(index)];
}

}  // namespace termshade
