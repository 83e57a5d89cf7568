#pragma once

#include <cstdint>
#include <utility>

#include "raster/FixedPoint.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {

/// The edge function of a -> b (fixed-point cell units, SPEC 5): positive
/// inside a clockwise-on-screen (v down) triangle, its value at the origin
/// sample biased by 1 on edges that are neither top nor left, so a sample
/// exactly on a shared edge belongs to one side only; steps per sample right
/// and down. Exact in 64 bits inside the guard band.
struct EdgeFunction {
  int64_t stepX = 0;
  int64_t stepY = 0;
  int64_t atOrigin = 0;
};

inline EdgeFunction MakeEdgeFunction(const RasterVertex& a, const RasterVertex& b, int64_t originX,
                                     int64_t originY) {
  const int64_t dx = int64_t{b.x} - a.x;
  const int64_t dy = int64_t{b.y} - a.y;
  const bool topLeft = dy < 0 || (dy == 0 && dx > 0);
  return {-dy * kFixedOne, dx * kFixedOne,
          dx * (originY - a.y) - dy * (originX - a.x) - (topLeft ? 0 : 1)};
}

/// A triangle's corners in clockwise order on screen, and twice its area
/// (positive; 0 when it covers nothing).
struct ClockwiseTriangle {
  const RasterVertex* v0;
  const RasterVertex* v1;
  const RasterVertex* v2;
  int64_t area;
};

inline ClockwiseTriangle OrientClockwise(const RasterVertex& a, const RasterVertex& b,
                                         const RasterVertex& c) {
  ClockwiseTriangle t{
      &a, &b, &c,
      (int64_t{b.x} - a.x) * (int64_t{c.y} - a.y) - (int64_t{b.y} - a.y) * (int64_t{c.x} - a.x)};
  if (t.area < 0) {
    std::swap(t.v1, t.v2);
    t.area = -t.area;
  }
  return t;
}

}  // namespace termshade
