#pragma once

#include "geometry/Vec3.h"

namespace termshade {

/// Central projection onto z = -d and the screen-to-cell map of SPEC 3.
struct Projection {
  double d = 1.0;           ///< screen distance, in cell widths
  double cx = 0.0;          ///< image center column, in cells
  double cy = 0.0;          ///< image center row, in cells
  double cellAspect = 2.0;  ///< cell height / cell width
};

/// A projected point: cell coordinates and w = 1 / (-z) of the eye-space point.
struct CellPoint {
  double u = 0.0;
  double v = 0.0;
  double w = 0.0;
};

/// Projects an eye-space point with z < 0.
inline CellPoint ProjectToCell(const Projection& proj, Vec3 pEye) {
  const double w = -1.0 / pEye.z;
  const double xScreen = proj.d * pEye.x * w;
  const double yScreen = proj.d * pEye.y * w;
  return {proj.cx + xScreen, proj.cy - yScreen / proj.cellAspect, w};
}

/// Chooses d and the center so that a sphere of the given radius about the
/// world origin, seen from distance rho, fills `fillFraction` of the smaller
/// half-extent of a widthCells x heightCells view.
Projection FitProjection(double radiusModelUnits, double rhoModelUnits, int widthCells,
                         int heightCells, double cellAspect, double fillFraction = 0.9);

}  // namespace termshade
