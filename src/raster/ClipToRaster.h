#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "geometry/ClipPolygon.h"
#include "geometry/Mat4.h"
#include "geometry/Projection.h"
#include "geometry/Scene.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {

/// The most corners a triangle clipped by the view's planes can have.
inline constexpr size_t kClippedCornersMax = 10;

/// A triangle that crosses a clip plane: its world corners taken to eye space
/// (recomputed rather than stored for every vertex), clipped by the view's
/// planes, projected and snapped to cell coordinates. Returns the corner count
/// of the convex polygon (< 3: nothing to draw); a fan from corner 0 covers it.
size_t ClipToRaster(const Scene& scene, uint32_t triangle, const Mat4& eyeFromWorld,
                    const ViewClipPlanes& clipPlanes, const Projection& projection,
                    std::array<RasterVertex, kClippedCornersMax>& projected);

}  // namespace termshade
