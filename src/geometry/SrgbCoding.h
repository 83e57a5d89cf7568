#pragma once

#include <cstdint>

namespace termshade {

/// Linear light of an 8-bit sRGB component (IEC 61966-2-1), from a table.
float LinearOfSrgb8(uint8_t component);
/// The same in double precision, computed.
double LinearOfSrgb8Exact(uint8_t component);
/// The 8-bit sRGB component of linear light, clamped to [0, 1] and rounded.
uint8_t Srgb8OfLinear(double linear);

}  // namespace termshade
