#pragma once

namespace termshade {

/// A colour as a model file gives it: linear components in [0, 1].
struct Rgb {
  float r = 0.0f;
  float g = 0.0f;
  float b = 0.0f;
};

inline bool operator==(Rgb a, Rgb b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

/// Relative luminance of a linear colour (ITU-R BT.709 weights).
inline double LinearLuminance(Rgb c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

}  // namespace termshade
