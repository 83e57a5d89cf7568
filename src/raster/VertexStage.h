#pragma once

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

/// One vertex by ProjectVertices' direct path, for a vertex that takes it (in
/// front of twice the near distance, within half the guard band): the same
/// operations in the same order, so the same bits.
inline RasterVertex ProjectDirect(const Mat4& eyeFromWorld, const Projection& proj, Vec3 pWorld) {
  const Vec3 pEye = TransformPoint(eyeFromWorld, pWorld);
  const double w = -1.0 / pEye.z;
  const double xCells = proj.d * pEye.x * w, yCells = proj.d / proj.cellAspect * pEye.y * w;
  return {SnapToFixed(proj.cx + xCells), SnapToFixed(proj.cy - yCells), static_cast<float>(w)};
}

}  // namespace termshade
