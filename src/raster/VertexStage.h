#pragma once

#include <cstdint>
#include <span>

#include "geometry/ClipPolygon.h"
#include "geometry/Mat4.h"
#include "geometry/Projection.h"
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

}  // namespace termshade
