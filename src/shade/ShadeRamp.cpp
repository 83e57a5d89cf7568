#include "shade/ShadeRamp.h"

#include <algorithm>
#include <cmath>

namespace termshade {

std::optional<std::string> ShadeRamp::Problem(const std::string& glyphs) {
  if (glyphs.empty()) return "the ramp needs at least one character";
  if (glyphs.size() > 64) return "the ramp has more than 64 characters";
  for (char c : glyphs) {
    if (c == ' ') return "the ramp may not contain a blank (the background is blank)";
    if (c < 0x21 || c > 0x7e) return "the ramp must be printable ASCII characters";
  }
  return std::nullopt;
}

int ShadeRamp::LevelFor(double intensity) const {
  const double clamped = std::isnan(intensity) ? 0.0 : std::clamp(intensity, 0.0, 1.0);
  const int level = static_cast<int>(std::floor(clamped * LevelCount()));
  return std::min(level, LevelCount() - 1);
}

}  // namespace termshade
