#pragma once

#include <cstdint>

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"

namespace termshade {

/// A projected vertex: cell coordinates in fixed point (kSubCellBits) and w = 1/(-z_eye).
struct RasterVertex {
  int32_t x = 0;
  int32_t y = 0;
  float w = 0.0F;
};

enum class DepthRule {
  kNearestWins,  ///< Z-buffer: larger w wins; equal w goes to the lower face number
  kOverwrite,    ///< painter and cull: the later triangle wins
};

/// Covers the cell-center samples inside the triangle (either winding) with
/// faceNumber, by the top-left fill rule on exact integer edge functions, so
/// triangles sharing an edge cover each sample on it exactly once. Returns
/// the number of samples written.
int RasterizeTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                      uint32_t faceNumber, DepthRule rule, DepthBuffer& depth, CellBuffer& cells);

}  // namespace termshade
