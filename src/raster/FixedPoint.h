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

/// Rounds half away from zero; callers keep |cells| below kGuardBandCells.
inline int32_t SnapToFixed(double cells) {
  const double scaled = cells * kFixedOne;
  return static_cast<int32_t>(scaled + (scaled >= 0.0 ? 0.5 : -0.5));
}

}  // namespace termshade
