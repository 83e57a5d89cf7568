#pragma once

#include <span>

#include "geometry/Vec3.h"

namespace termshade {

/// Newell's normal of a polygon: twice its vector area. Right for collinear
/// leading vertices and slightly non-planar polygons (Sutherland, Sproull &
/// Schumacker 1974; Foley et al., "Computer Graphics", 11.1.3).
template <typename CornerToPoint>
Vec3 NewellNormal(size_t cornerCount, CornerToPoint pointAt) {
  Vec3 sum;
  if (cornerCount == 0) return sum;
  // Centering on the first corner keeps the sum accurate far from the origin.
  const Vec3 origin = pointAt(0);
  for (size_t i = 0; i < cornerCount; ++i) {
    const Vec3 a = pointAt(i) - origin;
    const Vec3 b = pointAt(i + 1 == cornerCount ? 0 : i + 1) - origin;
    sum.x += (a.y - b.y) * (a.z + b.z);
    sum.y += (a.z - b.z) * (a.x + b.x);
    sum.z += (a.x - b.x) * (a.y + b.y);
  }
  return sum;
}

inline Vec3 NewellNormal(std::span<const Vec3> points) {
  return NewellNormal(points.size(), [&](size_t i) { return points[i]; });
}

}  // namespace termshade
