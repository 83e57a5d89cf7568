#include "geometry/FitCamera.h"

namespace termshade {

Camera FitCamera(const Scene& scene, const ViewParams& view, int widthCells, int heightCells,
                 double cellAspect) {
  return FitCameraAt(scene, view, DefaultView(scene.diagonalModelUnits).rho, widthCells,
                     heightCells, cellAspect);
}

Camera FitCameraAt(const Scene& scene, const ViewParams& view, double fitRho, int widthCells,
                   int heightCells, double cellAspect) {
  return {view, FitProjection(scene.radiusModelUnits, fitRho, widthCells, heightCells, cellAspect)};
}

}  // namespace termshade
