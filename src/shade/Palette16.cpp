#include "shade/Palette16.h"

#include <cmath>
#include <limits>
#include <vector>

#include "geometry/SrgbCoding.h"

namespace termshade {
namespace {

struct Lab {
  double l, a, b;
};

double LabCurve(double t) {
  constexpr double kDelta = 6.0 / 29.0;
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

// sRGB to CIELAB (D65 white).
Lab ToLab(Srgb8 colour) {
  const double r = LinearOfSrgb8Exact(colour.r), g = LinearOfSrgb8Exact(colour.g),
               b = LinearOfSrgb8Exact(colour.b);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const double fx = LabCurve(x), fy = LabCurve(y), fz = LabCurve(z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

bool KeepsContrast(Srgb8 colour, Background background) {
  const double luminance = RelativeLuminance(colour);
  return background == Background::kDark ? luminance >= kDarkFloorLuminance
                                         : luminance <= kLightCeilingLuminance;
}

// Lab chroma below this is grey (the face keeps the grey entries).
constexpr double kGreyChroma = 12.0;

// The entries a face of this colour may take: its hue's normal and bright
// entry and black, or the greys.
std::vector<int> FamilyOf(Srgb8 face) {
  const Lab lab = ToLab(face);
  if (std::hypot(lab.a, lab.b) < kGreyChroma) return {0, 8, 7, 15};
  int hue = 1;
  double bestAngle = std::numeric_limits<double>::infinity();
  for (int index = 9; index <= 14; ++index) {  // the bright entries' hues are the clearest
    const Lab entry = ToLab(kXtermPalette16[static_cast<size_t>(index)]);
    const double angle = std::abs(std::remainder(
        std::atan2(lab.b, lab.a) - std::atan2(entry.b, entry.a), 2.0 * 3.14159265358979));
    if (angle < bestAngle) {
      bestAngle = angle;
      hue = index - 8;
    }
  }
  return {0, hue, hue + 8};
}

}  // namespace

int Nearest16Colour(Srgb8 shade, Srgb8 face, Background background) {
  const double lightness = ToLab(shade).l;
  int best = background == Background::kDark ? 7 : 0;  // every background keeps one of these
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const int index : FamilyOf(face)) {
    const Srgb8 entry = kXtermPalette16[static_cast<size_t>(index)];
    if (!KeepsContrast(entry, background)) continue;
    const double distance = std::abs(ToLab(entry).l - lightness);
    if (distance < bestDistance) {  // ties keep the darker entry
      best = index;
      bestDistance = distance;
    }
  }
  return best;
}

}  // namespace termshade
