#include "raster/DetailPick.h"

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

}  // namespace termshade
