#pragma once

#include <algorithm>
#include <cmath>
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

/// False when the triangle's bounding box holds no cell-center sample of a
/// widthCells x heightCells view: the cheap early-out for sub-cell triangles.
inline bool MayCoverSample(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                           int widthCells, int heightCells) {
  // Samples sit at 256 k + 128: the box must hold one in x and one in y.
  // Plain two-way min and max: this runs for every triangle of every frame.
  const int32_t minX = std::min(a.x, std::min(b.x, c.x)), maxX = std::max(a.x, std::max(b.x, c.x));
  const int32_t firstCol = std::max(0, (minX + 127) >> 8);
  const int32_t lastCol = std::min(widthCells - 1, (maxX - 128) >> 8);
  if (firstCol > lastCol) return false;
  const int32_t minY = std::min(a.y, std::min(b.y, c.y)), maxY = std::max(a.y, std::max(b.y, c.y));
  const int32_t firstRow = std::max(0, (minY + 127) >> 8);
  const int32_t lastRow = std::min(heightCells - 1, (maxY - 128) >> 8);
  return firstRow <= lastRow;
}

/// True when some cell-center sample k + 0.5 (k in [0, limit)) lies in
/// [low, high] (cells, in x or y): the bounds tests of whole groups of triangles.
inline bool RangeHoldsSample(double low, double high, int limit) {
  const double first = std::max(0.0, std::ceil(low - 0.5));
  const double last = std::min(limit - 1.0, std::floor(high - 0.5));
  return first <= last;
}

/// How depth is interpolated and stored. The product uses kFloatInverseZ; the
/// others are kept to measure against it (termshade bench).
enum class DepthFormat {
  kFloatInverseZ,    ///< 1/z linear in screen space, in float (SPEC 5)
  kLinearZ,          ///< z itself interpolated linearly: wrong on purpose
  kFixed16InverseZ,  ///< 1/z quantized to 16 bits over the frame's range (old game books)
};

struct DepthEncoding {
  DepthFormat format = DepthFormat::kFloatInverseZ;
  float fixedScale = 1.0F;  ///< kFixed16InverseZ: w x fixedScale spans 0..65535
};

enum class DepthRule {
  kNearestWins,  ///< Z-buffer: larger w wins; equal w goes to the lower face number
  kOverwrite,    ///< painter and cull: the later triangle wins
  kCoverOnly,    ///< as kOverwrite, the depth buffer neither read nor written
};

/// The rows [first, end) a rasterizer may write: one screen band of a
/// threaded frame, or every row.
struct RowRange {
  int first = 0;
  int end = 1 << 30;
};

/// Covers the cell-center samples inside the triangle (either winding) with
/// faceNumber, by the top-left fill rule on exact integer edge functions, so
/// triangles sharing an edge cover each sample on it exactly once. Returns
/// the number of samples written. Within `rows` only; each sample gets the
/// same value whatever the range (the edge functions are exact integers).
int RasterizeTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                      uint32_t faceNumber, DepthRule rule, DepthBuffer& depth, CellBuffer& cells,
                      const DepthEncoding& encoding = {}, RowRange rows = {});

/// The classic scanline algorithm of course notes, kept for comparison:
/// vertices sorted by row, edge x and w stepped incrementally in float per
/// row and column, spans filled between the edges at sample centers. Not
/// watertight on shared edges (float steps drift).
int RasterizeTriangleScanline(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                              uint32_t faceNumber, DepthRule rule, DepthBuffer& depth,
                              CellBuffer& cells);

}  // namespace termshade
