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

/// Relative luminance of linear components (ITU-R BT.709 weights).
inline double LinearLuminance(double r, double g, double b) {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}
inline double LinearLuminance(Rgb c) {
  return LinearLuminance(c.r, c.g, c.b);
}

}  // namespace termshade
