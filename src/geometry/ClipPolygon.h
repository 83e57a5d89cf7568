#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "geometry/Projection.h"
#include "geometry/Vec3.h"

namespace termshade {

/// A half-space Dot(normal, p) + offset >= 0 in eye space.
struct ClipPlane {
  Vec3 normal;
  double offset = 0.0;
  double Distance(Vec3 p) const { return Dot(normal, p) + offset; }
};

/// Near plane z = -near, then four guard-band planes that keep projected cell
/// coordinates within the rasterizer's fixed-point range.
using ViewClipPlanes = std::array<ClipPlane, 5>;
ViewClipPlanes MakeViewClipPlanes(const Projection& projection, double nearModelUnits);

/// Bit i set when p is outside plane i (NaN is outside every plane). Inline:
/// it runs once per vertex per frame.
inline unsigned OutCode(const ViewClipPlanes& planes, Vec3 pEye) {
  unsigned code = 0;
  for (unsigned i = 0; i < planes.size(); ++i) {
    code |= static_cast<unsigned>(!(planes[i].Distance(pEye) >= 0.0)) << i;
  }
  return code;
}

/// A convex polygon: a clipped triangle has at most 3 + 5 corners.
struct ClippedPolygon {
  std::array<Vec3, 10> corners{};
  size_t count = 0;
};

/// Sutherland-Hodgman clip of a triangle. A crossing point is computed from
/// the edge's endpoints in a fixed order, so triangles sharing an edge get
/// bit-identical new corners (no cracks, no double cover).
void ClipTriangle(const std::array<Vec3, 3>& triangleEye, const ViewClipPlanes& planes,
                  ClippedPolygon& out);

/// Clips a segment; false when nothing of it is inside.
bool ClipSegment(Vec3& aEye, Vec3& bEye, const ViewClipPlanes& planes);

}  // namespace termshade
