#pragma once

#include "geometry/Scene.h"

namespace termshade {

/// Median time of one frame over a turntable (theta steps of 0.1 rad from the
/// default view) at the given size, in this process, in milliseconds; the
/// first frame only warms the caches.
double MedianTurntableFrameMs(const Scene& scene, int widthCells, int heightCells,
                              int timedFrames = 20);

}  // namespace termshade
