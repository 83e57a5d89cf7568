#pragma once

#include <array>
#include <cstdint>

namespace termshade {

/// Linear light of each 8-bit sRGB component (IEC 61966-2-1), by component.
const std::array<float, 256>& LinearOfSrgb8Table();
/// Linear light of an 8-bit sRGB component, from the table.
inline float LinearOfSrgb8(uint8_t component) {
  return LinearOfSrgb8Table()[component];
}
/// The same in double precision, computed.
double LinearOfSrgb8Exact(uint8_t component);
/// The 8-bit sRGB component of linear light, clamped to [0, 1] and rounded.
uint8_t Srgb8OfLinear(double linear);

}  // namespace termshade
