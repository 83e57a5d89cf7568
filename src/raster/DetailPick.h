#pragma once

#include <cstddef>

#include "geometry/Camera.h"
#include "geometry/LevelOfDetail.h"
#include "geometry/Scene.h"
#include "raster/RenderOptions.h"

namespace termshade {

/// The scene a frame draws: the exact one, or a level of detail.
struct DetailPick {
  const Scene* scene = nullptr;
  size_t level = 0;  ///< 0: exact; i: levels->levels[i - 1]
};

/// The level ChooseDetailLevel picks for this frame's sample grid (the glyph
/// mode's, or the variant's); the exact scene when levels is null or empty,
/// or for the wire frame (whose lines are the model's own edges).
DetailPick PickDetail(const DetailLevels* levels, const Scene& exact, const Camera& camera,
                      const RenderOptions& options,
                      double samplesPerTriangle = DetailTarget{}.samplesPerTriangle);

/// The clustered copy (BuildClusteredLevel) for this frame: cells of one
/// sample at the model's nearest point, so it moves by about a sample.
DetailLevel ClusteredLevelFor(const Scene& exact, const Camera& camera,
                              const RenderOptions& options);

}  // namespace termshade
