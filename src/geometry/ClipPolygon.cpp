#include "geometry/ClipPolygon.h"

#include <tuple>

#include "geometry/FixedRange.h"

namespace termshade {
namespace {

bool LexLess(Vec3 a, Vec3 b) {
  return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

// The point where segment ab crosses the plane, the same for ab and ba.
Vec3 Crossing(Vec3 a, Vec3 b, const ClipPlane& plane) {
  if (LexLess(b, a)) std::swap(a, b);
  const double da = plane.Distance(a), db = plane.Distance(b);
  const double t = da / (da - db);
  return a + (b - a) * t;
}

}  // namespace

ViewClipPlanes MakeViewClipPlanes(const Projection& projection, double nearModelUnits) {
  // |X| <= gx and |Y| <= gy, written as half-spaces through the eye (z < 0).
  const double gx = kClipRangeCells - projection.cx;
  const double gy = (kClipRangeCells - projection.cy) * projection.cellAspect;
  const double d = projection.d;
  return {{
      {{0, 0, -1}, -nearModelUnits},
      {{-d, 0, -gx}, 0},
      {{d, 0, -gx}, 0},
      {{0, -d, -gy}, 0},
      {{0, d, -gy}, 0},
  }};
}

void ClipTriangle(const std::array<Vec3, 3>& triangleEye, const ViewClipPlanes& planes,
                  ClippedPolygon& out) {
  ClippedPolygon scratch;
  out.count = 3;
  for (size_t i = 0; i < 3; ++i) out.corners[i] = triangleEye[i];
  for (const ClipPlane& plane : planes) {
    scratch.count = 0;
    for (size_t i = 0; i < out.count; ++i) {
      const Vec3 a = out.corners[i];
      const Vec3 b = out.corners[(i + 1) % out.count];
      const bool aIn = plane.Distance(a) >= 0.0, bIn = plane.Distance(b) >= 0.0;
      if (aIn) scratch.corners[scratch.count++] = a;
      if (aIn != bIn) scratch.corners[scratch.count++] = Crossing(a, b, plane);
    }
    out = scratch;
    if (out.count < 3) {
      out.count = 0;
      return;
    }
  }
}

bool ClipSegment(Vec3& aEye, Vec3& bEye, const ViewClipPlanes& planes) {
  for (const ClipPlane& plane : planes) {
    const bool aIn = plane.Distance(aEye) >= 0.0, bIn = plane.Distance(bEye) >= 0.0;
    if (!aIn && !bIn) return false;
    if (!aIn) aEye = Crossing(aEye, bEye, plane);
    if (!bIn) bEye = Crossing(aEye, bEye, plane);
  }
  return true;
}

}  // namespace termshade
