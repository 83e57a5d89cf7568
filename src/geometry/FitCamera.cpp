#include "geometry/FitCamera.h"

#include "geometry/OrbitFit.h"

namespace termshade {

Camera FitCamera(const Scene& scene, const ViewParams& view, int widthCells, int heightCells,
                 double cellAspect, Framing framing) {
  return FitCameraAt(scene, view, DefaultView(scene.diagonalModelUnits).rho, widthCells,
                     heightCells, cellAspect, framing);
}

Camera FitCameraAt(const Scene& scene, const ViewParams& view, double fitRho, int widthCells,
                   int heightCells, double cellAspect, Framing framing) {
  if (framing == Framing::kOrbit) {
    return {view, FitOrbitProjection(scene.radiusModelUnits, scene.horizontalRadiusModelUnits,
                                     fitRho, widthCells, heightCells, cellAspect)};
  }
  return {view, FitProjection(scene.radiusModelUnits, fitRho, widthCells, heightCells, cellAspect)};
}

}  // namespace termshade
