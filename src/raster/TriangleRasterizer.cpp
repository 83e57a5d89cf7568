#include "raster/TriangleRasterizer.h"

#include <algorithm>

#include "raster/FixedPoint.h"

namespace termshade {
namespace {

struct Edge {
  int64_t stepX = 0;  // change of the edge function per cell to the right
  int64_t stepY = 0;  // change per cell down
  int64_t atOrigin = 0;
};

// Edge function of a -> b at p, positive on the inside of a clockwise-on-screen
// (v down) triangle; the bias drops samples exactly on edges that are not top
// or left, so a shared edge belongs to one side only.
Edge MakeEdge(const RasterVertex& a, const RasterVertex& b, int64_t originX, int64_t originY) {
  const int64_t dx = int64_t{b.x} - a.x;
  const int64_t dy = int64_t{b.y} - a.y;
  const bool topLeft = dy < 0 || (dy == 0 && dx > 0);
  Edge e;
  e.stepX = -dy * kFixedOne;
  e.stepY = dx * kFixedOne;
  e.atOrigin = dx * (originY - a.y) - dy * (originX - a.x) - (topLeft ? 0 : 1);
  return e;
}

// Range of cells whose sample (c * 256 + 128) lies in [low, high]; >> is a
// floor division by 256 (arithmetic shift, C++20).
void SampleRange(int32_t low, int32_t high, int limit, int& first, int& last) {
  first = std::max(0, (low - kFixedHalf + kFixedOne - 1) >> kSubCellBits);
  last = std::min(limit - 1, (high - kFixedHalf) >> kSubCellBits);
}

}  // namespace

int RasterizeTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                      uint32_t faceNumber, DepthRule rule, DepthBuffer& depth, CellBuffer& cells) {
  // Step 1: the cells whose samples the bounding box holds; most triangles
  // of a fine mesh hold none and stop here.
  int col0 = 0, col1 = 0, row0 = 0, row1 = 0;
  SampleRange(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), cells.WidthCells(), col0, col1);
  if (col0 > col1) return 0;
  SampleRange(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), cells.HeightCells(), row0, row1);
  if (row0 > row1) return 0;

  // Step 2: orient clockwise on screen (positive area); drop empty triangles.
  const RasterVertex* v0 = &a;
  const RasterVertex* v1 = &b;
  const RasterVertex* v2 = &c;
  int64_t area = (int64_t{v1->x} - v0->x) * (int64_t{v2->y} - v0->y) -
                 (int64_t{v1->y} - v0->y) * (int64_t{v2->x} - v0->x);
  if (area == 0) return 0;
  if (area < 0) {
    std::swap(v1, v2);
    area = -area;
  }

  // Step 3: edge functions at the first sample, stepped per cell.
  const int64_t originX = int64_t{col0} * kFixedOne + kFixedHalf;
  const int64_t originY = int64_t{row0} * kFixedOne + kFixedHalf;
  const Edge e12 = MakeEdge(*v1, *v2, originX, originY);  // weight of v0
  const Edge e20 = MakeEdge(*v2, *v0, originX, originY);  // weight of v1
  const Edge e01 = MakeEdge(*v0, *v1, originX, originY);  // weight of v2
  // 1/z is linear in screen space: w = sum of edge weights times vertex w / area.
  const float invArea = 1.0F / static_cast<float>(area);
  const float k0 = v0->w * invArea, k1 = v1->w * invArea, k2 = v2->w * invArea;

  // Step 4: visit samples; write the nearest (or latest) surface.
  int written = 0;
  int64_t row12 = e12.atOrigin, row20 = e20.atOrigin, row01 = e01.atOrigin;
  auto& faces = cells.FaceNumbers();
  for (int row = row0; row <= row1; ++row) {
    int64_t w12 = row12, w20 = row20, w01 = row01;
    size_t index = cells.Index(col0, row);
    for (int col = col0; col <= col1; ++col, ++index) {
      if ((w12 | w20 | w01) >= 0) {
        // The fill-rule bias (1 unit in 2^16 per cell^2) is negligible in the weights.
        const float w = static_cast<float>(w12) * k0 + static_cast<float>(w20) * k1 +
                        static_cast<float>(w01) * k2;
        float& stored = depth.At(index);
        const bool wins = rule == DepthRule::kOverwrite || w > stored ||
                          (w == stored && faceNumber < faces[index]);
        if (wins) {
          stored = w;
          faces[index] = faceNumber;
          ++written;
        }
      }
      w12 += e12.stepX;
      w20 += e20.stepX;
      w01 += e01.stepX;
    }
    row12 += e12.stepY;
    row20 += e20.stepY;
    row01 += e01.stepY;
  }
  return written;
}

}  // namespace termshade
