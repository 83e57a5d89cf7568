#pragma once

#include <cmath>
#include <cstdint>

namespace termshade {

/// Cell coordinates snapped to 1/256 cell (SPEC 5: 8 sub-cell bits).
constexpr int kSubCellBits = 8;
constexpr int32_t kFixedOne = 1 << kSubCellBits;
constexpr int32_t kFixedHalf = kFixedOne / 2;

/// Largest |cell coordinate| the rasterizer accepts: keeps every edge-function
/// product of fixed-point differences below 2^62.
constexpr double kGuardBandCells = 1 << 21;

inline int32_t SnapToFixed(double cells) {
  return static_cast<int32_t>(std::lround(cells * kFixedOne));
}

}  // namespace termshade
