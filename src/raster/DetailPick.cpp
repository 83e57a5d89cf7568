#include "raster/DetailPick.h"

#include <algorithm>

namespace termshade {

DetailPick PickDetail(const DetailLevels* levels, const Scene& exact, const Camera& camera,
                      const RenderOptions& options, double samplesPerTriangle) {
  if (levels == nullptr || levels->levels.empty() || options.method == Method::kWire) {
    return {&exact, 0};
  }
  const SampleGrid grid = FrameSampleGrid(options);
  DetailTarget target;
  target.samplesAcross = grid.across;
  target.samplesDown = grid.down;
  target.samplesPerTriangle = samplesPerTriangle;
  const size_t level = ChooseDetailLevel(*levels, exact, camera, target);
  return {&DetailScene(*levels, exact, level), level};
}

DetailLevel ClusteredLevelFor(const Scene& exact, const Camera& camera,
                              const RenderOptions& options) {
  const SampleGrid grid = FrameSampleGrid(options);
  const double nearestModelUnits =
      std::max(camera.view.rho - exact.radiusModelUnits, 1e-3 * exact.radiusModelUnits);
  const double samplesPerUnit =
      camera.projection.d * std::max(grid.across, grid.down) / nearestModelUnits;
  return BuildClusteredLevel(exact, 1.0 / samplesPerUnit);
}

}  // namespace termshade
