#pragma once

#include <cmath>
#include <cstdint>
#include <span>

#include "geometry/ClipPolygon.h"
#include "geometry/Mat4.h"
#include "geometry/Projection.h"
#include "raster/FixedPoint.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {

/// Where the vertex stage writes, one entry per vertex.
struct VertexStageOutput {
  RasterVertex* raster = nullptr;  ///< snapped cell position and w; zero when clipped
  uint8_t* outCodes = nullptr;     ///< clip planes the vertex is outside of (0: in view)
  double* eyeZ = nullptr;          ///< eye z, for the painter's sort (may be null)
};

/// Transforms every vertex to eye space and projects those inside every clip
/// plane to snapped cell positions; returns the largest w = 1/(-z) seen.
/// floatGeometry: the measured variant that computes in float.
float ProjectVertices(std::span<const Vec3> verticesWorld, const Mat4& eyeFromWorld,
                      const Projection& proj, const ViewClipPlanes& planes, bool floatGeometry,
                      const VertexStageOutput& out);

/// The per-frame constants of the projection and the conservative inside test.
struct VertexStageConstants {
  Mat4 m;
  double d, vScale, cx, cy;
  double nearZ;           ///< twice the near distance: surely in front
  double xLimit, yLimit;  ///< half the guard band: surely inside it
};

/// One vertex at a time, bit for bit as ProjectVertices projects it: for
/// stages that transform only the vertices they draw.
class VertexProjector {
 public:
  VertexProjector(const Mat4& eyeFromWorld, const Projection& proj, const ViewClipPlanes& planes,
                  bool floatGeometry);
  void Project(Vec3 pWorld, RasterVertex& raster, uint8_t& outCode) const {
    if (!floatGeometry_) {
      // The direct path of ProjectVertices, the same operations in the same order.
      const Vec3 pEye = TransformPoint(k_.m, pWorld);
      const double w = -1.0 / pEye.z;
      const double xCells = k_.d * pEye.x * w, yCells = k_.vScale * pEye.y * w;
      if (pEye.z <= -k_.nearZ && std::fabs(xCells) <= k_.xLimit &&
          std::fabs(yCells) <= k_.yLimit) {
        outCode = 0;
        raster = {SnapToFixed(k_.cx + xCells), SnapToFixed(k_.cy - yCells), static_cast<float>(w)};
        return;
      }
    }
    ProjectAny(pWorld, raster, outCode);
  }

 private:
  void ProjectAny(Vec3 pWorld, RasterVertex& raster, uint8_t& outCode) const;

  VertexStageConstants k_;
  Projection proj_;
  ViewClipPlanes planes_;
  bool floatGeometry_;
};

}  // namespace termshade
