#pragma once

#include "geometry/Vec3.h"

namespace termshade {

enum class ShadeMode {
  kContrast,  ///< textbook: n.s from min..max over the visible faces onto the whole ramp
  kLambert,   ///< ambient + (1 - ambient) max(0, n.s): stable while orbiting
};

/// The sun of SPEC 4, in eye coordinates: light from the upper left front.
Vec3 DefaultSunEye();

/// A unit sun direction in eye space from two angles (radians) about the eye's
/// axes; (0, 0) is the default sun. Lets the light orbit like the eye does.
Vec3 SunFromAngles(double azimuth, double elevation);

constexpr double kDefaultAmbient = 0.1;

double LambertIntensity(double nDotSun, double ambient);

/// Contrast mapping of n.s onto [0, 1], given the range over the visible faces.
/// A range of no width (one visible normal) falls back to Lambert's intensity.
double ContrastIntensity(double nDotSun, double minDot, double maxDot, double ambient);

}  // namespace termshade
