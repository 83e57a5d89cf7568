#pragma once

#include "geometry/Projection.h"

namespace termshade {

/// The viewer's framing (`render --fit`): d and the center such that every
/// point within radiusModelUnits of the world origin and within
/// horizontalRadiusModelUnits of its up (z) axis projects inside the
/// widthCells x heightCells view, half a cell from its edges, seen from
/// distance rho at any theta and phi. Heights take the bounding sphere
/// (phi can bring any point up); widths the cylinder about the up axis (the
/// eye's x is always horizontal).
Projection FitOrbitProjection(double radiusModelUnits, double horizontalRadiusModelUnits,
                              double rhoModelUnits, int widthCells, int heightCells,
                              double cellAspect);

/// The largest |x / z| of eye-space points within the sphere and the
/// cylinder, seen from distance rho (> radius): the horizontal half-angle's tangent.
double HorizontalTangent(double radiusModelUnits, double horizontalRadiusModelUnits,
                         double rhoModelUnits);

}  // namespace termshade
