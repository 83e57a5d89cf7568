#include "geometry/SrgbCoding.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace termshade {

double LinearOfSrgb8Exact(uint8_t component) {
  const double c = component / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

const std::array<float, 256>& LinearOfSrgb8Table() {
  static const std::array<float, 256> kTable = [] {
    std::array<float, 256> table{};
    for (int i = 0; i < 256; ++i) {
      table[i] = static_cast<float>(LinearOfSrgb8Exact(static_cast<uint8_t>(i)));
    }
    return table;
  }();
  return kTable;
}

uint8_t Srgb8OfLinear(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(encoded * 255.0));
}

}  // namespace termshade
