#include "geometry/ViewParams.h"

namespace termshade {

ViewLimits LimitsForDiagonal(double diagonalModelUnits) {
  // A single point or empty model still gets a usable, non-zero distance.
  const double diagonal = diagonalModelUnits > 0.0 ? diagonalModelUnits : 1.0;
  const double rhoMin = 0.6 * diagonal;
  return {rhoMin, 1000.0 * rhoMin};
}

ViewParams DefaultView(double diagonalModelUnits) {
  return {3.0 * LimitsForDiagonal(diagonalModelUnits).rhoMin, 0.3, 1.3};
}

}  // namespace termshade
