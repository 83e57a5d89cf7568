#pragma once

#include <cstdint>

#include "raster/SampleFrame.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {

/// Draws triangles into a SampleFrame cell by cell (per cell the k x m
/// samples' edge functions from the cell's first by fixed per-sample offsets,
/// 32-bit and four at a time); 1x2 cells and triangles too big for 32-bit
/// edge values sample by sample. Every sample gets exactly what
/// RasterizeTriangle gives it on the same frame stored row-major (positions
/// in 1/256 sample, the same top-left rule, the same float depth and depth
/// rule), with kFloatInverseZ depth. Grids 1x2, 2x2, 2x3, 2x4.
class SampledRasterizer {
 public:
  /// False for a grid it has no specialisation of.
  static bool Supports(SampleGrid grid);

  /// Whether this CPU runs the eight-lane (AVX2) path of 2x4 cells.
  static bool WideAvailable();

  /// Draws into `frame` (which Begin has sized) by `rule`; grid: Supports.
  /// wide: 2x4 cells eight lanes at a time where WideAvailable (same samples).
  SampledRasterizer(SampleFrame& frame, DepthRule rule, bool wide = true);

  /// One triangle, corners in sample coordinates (1/256 sample fixed point).
  void Draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
            uint32_t faceNumber) {
    draw_(a, b, c, faceNumber, frame_);
  }

  using DrawFunction = void (*)(const RasterVertex&, const RasterVertex&, const RasterVertex&,
                                uint32_t, SampleFrame&);

 private:
  SampleFrame& frame_;
  DrawFunction draw_ = nullptr;
};

}  // namespace termshade
