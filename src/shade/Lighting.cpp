#include "shade/Lighting.h"

#include <algorithm>
#include <cmath>

namespace termshade {

Vec3 DefaultSunEye() {
  return Normalized({-1.0, 1.0, 1.0});
}

Vec3 SunFromAngles(double azimuth, double elevation) {
  // Rotate the default sun about the eye's y axis, then tilt it about x.
  const Vec3 s = DefaultSunEye();
  const double ca = std::cos(azimuth), sa = std::sin(azimuth);
  const Vec3 turned{ca * s.x + sa * s.z, s.y, -sa * s.x + ca * s.z};
  const double ce = std::cos(elevation), se = std::sin(elevation);
  return Normalized({turned.x, ce * turned.y - se * turned.z, se * turned.y + ce * turned.z});
}

double LambertIntensity(double nDotSun, double ambient) {
  return ambient + (1.0 - ambient) * std::max(0.0, nDotSun);
}

double ContrastIntensity(double nDotSun, double minDot, double maxDot, double ambient) {
  const double range = maxDot - minDot;
  if (!(range > 1e-12)) return LambertIntensity(nDotSun, ambient);
  return std::clamp((nDotSun - minDot) / range, 0.0, 1.0);
}

}  // namespace termshade
