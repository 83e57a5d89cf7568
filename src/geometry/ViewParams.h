#pragma once

namespace termshade {

/// Spherical eye position about the world origin (SPEC 2): rho in model
/// units, theta and phi in radians.
struct ViewParams {
  double rho = 1.0;
  double theta = 0.3;
  double phi = 1.3;
};

/// Distance limits and the default view for a model of the given bounding-box diagonal.
struct ViewLimits {
  double rhoMin = 1.0;
  double rhoMax = 1000.0;
};

ViewLimits LimitsForDiagonal(double diagonalModelUnits);
ViewParams DefaultView(double diagonalModelUnits);

}  // namespace termshade
