#pragma once

namespace termshade {

/// Projected positions are kept within +-kClipRangeCells of the screen's
/// corner by clipping, below the rasterizer's fixed-point limit of 2^21 cells
/// (raster/FixedPoint.h), so no edge-function product can overflow.
constexpr double kClipRangeCells = 1.5 * (1 << 20);

}  // namespace termshade
