#include "geometry/Projection.h"

#include <algorithm>
#include <cmath>

namespace termshade {

Projection FitProjection(double radiusModelUnits, double rhoModelUnits, int widthCells,
                         int heightCells, double cellAspect, double fillFraction) {
  Projection proj;
  proj.cellAspect = cellAspect;
  proj.cx = 0.5 * widthCells;
  proj.cy = 0.5 * heightCells;
  // Screen units are cell widths; the view's half-height is rows * aspect / 2 of them.
  const double halfExtentScreen =
      fillFraction * std::min(0.5 * widthCells, 0.5 * heightCells * cellAspect);
  // A sphere of radius R at distance rho subtends a cone of half-angle asin(R/rho);
  // its projected radius is d tan(asin(R / rho)) = d R / sqrt(rho^2 - R^2).
  const double radius = radiusModelUnits > 0.0 ? radiusModelUnits : 1.0;
  const double rho = std::max(rhoModelUnits, radius * 1.2);
  const double tanHalfAngle = radius / std::sqrt(rho * rho - radius * radius);
  proj.d = halfExtentScreen / tanHalfAngle;
  return proj;
}

}  // namespace termshade
