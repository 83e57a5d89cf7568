#include "geometry/OrbitFit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace termshade {
namespace {

// Half the window less the margin: half a cell, or a tenth of a tiny window.
double HalfExtentLessMarginCells(int cells) {
  const double half = 0.5 * std::max(cells, 1);
  return half - std::min(0.5, 0.1 * half);
}

}  // namespace

double HorizontalTangent(double radiusModelUnits, double horizontalRadiusModelUnits,
                         double rhoModelUnits) {
  const double radius = radiusModelUnits, rho = rhoModelUnits;
  const double horizontal = std::min(horizontalRadiusModelUnits, radius);
  // A point's eye x and its component f towards the eye satisfy x^2 + f^2 <= R^2
  // and |x| <= r; x / (rho - f) grows with both. The sphere's tangent from the
  // eye touches at x = R sqrt(rho^2 - R^2) / rho; a narrower cylinder cuts it
  // off, and the corner (r, sqrt(R^2 - r^2)) is the widest point left.
  const double tangentX = radius * std::sqrt(rho * rho - radius * radius) / rho;
  if (horizontal >= tangentX) return radius / std::sqrt(rho * rho - radius * radius);
  return horizontal / (rho - std::sqrt(radius * radius - horizontal * horizontal));
}

Projection FitOrbitProjection(double radiusModelUnits, double horizontalRadiusModelUnits,
                              double rhoModelUnits, int widthCells, int heightCells,
                              double cellAspect) {
  Projection proj;
  proj.cellAspect = cellAspect;
  proj.cx = 0.5 * widthCells;
  proj.cy = 0.5 * heightCells;
  const double radius = radiusModelUnits > 0.0 ? radiusModelUnits : 1.0;
  const double horizontal = radiusModelUnits > 0.0 ? horizontalRadiusModelUnits : 1.0;
  // The eye stays outside the sphere (as FitProjection's fit).
  const double rho = std::max(rhoModelUnits, radius * 1.2);
  const double tanVertical = radius / std::sqrt(rho * rho - radius * radius);
  const double tanHorizontal = HorizontalTangent(radius, horizontal, rho);
  // Screen units are cell widths; a row is cellAspect of them.
  const double dForHeight = HalfExtentLessMarginCells(heightCells) * cellAspect / tanVertical;
  const double dForWidth = tanHorizontal > 0.0
                               ? HalfExtentLessMarginCells(widthCells) / tanHorizontal
                               : std::numeric_limits<double>::infinity();
  proj.d = std::min(dForHeight, dForWidth);
  return proj;
}

}  // namespace termshade
