#include "geometry/Angle.h"

#include <charconv>
#include <cmath>
#include <numbers>

namespace termshade {

std::optional<double> ParseAngleRadians(std::string_view text) {
  double scale = 1.0;
  if (text.ends_with("deg")) {
    scale = std::numbers::pi / 180.0;
    text.remove_suffix(3);
  } else if (text.ends_with("rad")) {
    text.remove_suffix(3);
  }
  if (text.starts_with('+')) {  // from_chars takes '-' only
    text.remove_prefix(1);
    if (text.starts_with('-')) return std::nullopt;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  if (!std::isfinite(value)) return std::nullopt;
  return value * scale;
}

}  // namespace termshade
