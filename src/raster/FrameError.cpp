#include "raster/FrameError.h"

#include "geometry/RayCast.h"

namespace termshade {

FaceErrorReport MeasureFaceError(const Scene& scene, const Camera& camera, bool cullBackFaces,
                                 const CellBuffer& cells, const FaceErrorOptions& options) {
  ReferenceRayCaster reference(scene, camera, cullBackFaces);
  reference.BinFaces(cells.WidthCells(), cells.HeightCells());
  FaceErrorReport report;
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const double u = col + 0.5, v = row + 0.5;
      const RaySample exact = reference.Cast(u, v);
      const uint32_t drawn = cells.FaceNumber(col, row);
      // Step 1: the edge band of either face.
      const bool nearEdge =
          reference.DistanceToFaceEdgeCells(exact.faceNumber, u, v) <= kEdgeBandCells ||
          reference.DistanceToFaceEdgeCells(drawn, u, v) <= kEdgeBandCells;
      // Step 2: the two nearest surfaces closer than the method can tell apart.
      bool tooClose = false;
      if (options.excludeCloseDepths && exact.faceNumber != 0 && exact.secondFaceNumber != 0) {
        const double wNear = 1.0 / exact.depth, wSecond = 1.0 / exact.secondDepth;
        const double tolerance = (reference.WGradientPerCell(exact.faceNumber) +
                                  reference.WGradientPerCell(exact.secondFaceNumber)) *
                                     kEdgeBandCells +
                                 options.relativeDepthResolution * wNear;
        tooClose = wNear - wSecond <= tolerance;
      }
      if (nearEdge || tooClose) {
        ++report.dontCareCells;
        continue;
      }
      ++report.comparedCells;
      if (drawn != exact.faceNumber) ++report.wrongCells;
    }
  }
  return report;
}

}  // namespace termshade
