#pragma once

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"

namespace termshade {

/// Face error of a frame against the exact reference (SPEC 8).
struct FaceErrorReport {
  int comparedCells = 0;  ///< cells outside the don't-care band
  int dontCareCells = 0;  ///< near a projected edge, or two surfaces too close in depth
  int wrongCells = 0;     ///< compared cells whose face differs from the reference
  double Share() const { return comparedCells > 0 ? double(wrongCells) / comparedCells : 0.0; }
};

/// Half-width of the edge band, in cells (SPEC 8: 2^-8).
constexpr double kEdgeBandCells = 1.0 / 256.0;

/// Depth resolution of the float 1/z Z-buffer, relative to w.
constexpr double kFloatRelativeDepthResolution = 1.0 / (1 << 20);

/// How the don't-care band is drawn.
struct FaceErrorOptions {
  double relativeDepthResolution = kFloatRelativeDepthResolution;
  bool excludeCloseDepths = true;  ///< false: only the edge band is left out
};

/// Compares the face map of `cells` (one sample per cell, at its center)
/// with the reference ray cast. Two surfaces count as "too close" when
/// their w = 1/(-z) differ by less than what snapping vertices by the edge
/// band moves either (|grad w| x band) plus relativeDepthResolution x w.
FaceErrorReport MeasureFaceError(const Scene& scene, const Camera& camera, bool cullBackFaces,
                                 const CellBuffer& cells, const FaceErrorOptions& options = {});

}  // namespace termshade
