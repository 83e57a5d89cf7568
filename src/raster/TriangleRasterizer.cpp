#include "raster/TriangleRasterizer.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "raster/EdgeFunction.h"
#include "raster/FixedPoint.h"

namespace termshade {
namespace {

// Range of cells whose sample (c * 256 + 128) lies in [low, high]; >> is a
// floor division by 256 (arithmetic shift, C++20).
void SampleRange(int32_t low, int32_t high, int limit, int& first, int& last) {
  first = std::max(0, (low - kFixedHalf + kFixedOne - 1) >> kSubCellBits);
  last = std::min(limit - 1, (high - kFixedHalf) >> kSubCellBits);
}

// Depth at a sample from the three edge weights, per format.
template <DepthFormat kFormat>
struct DepthInterpolator {
  float k0, k1, k2, scale;
  DepthInterpolator(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                    int64_t area, const DepthEncoding& encoding) {
    const float invArea = 1.0F / static_cast<float>(area);
    scale = encoding.fixedScale;
    if constexpr (kFormat == DepthFormat::kLinearZ) {
      k0 = invArea / v0.w;  // z = 1 / w at the vertices, interpolated as if linear
      k1 = invArea / v1.w;
      k2 = invArea / v2.w;
    } else {
      k0 = v0.w * invArea;
      k1 = v1.w * invArea;
      k2 = v2.w * invArea;
    }
  }
  float operator()(int64_t e12, int64_t e20, int64_t e01) const {
    const float value =
        static_cast<float>(e12) * k0 + static_cast<float>(e20) * k1 + static_cast<float>(e01) * k2;
    if constexpr (kFormat == DepthFormat::kLinearZ) return 1.0F / value;
    if constexpr (kFormat == DepthFormat::kFixed16InverseZ) {
      return std::min(65535.0F, std::floor(value * scale)) / scale;
    }
    return value;
  }
};

template <DepthFormat kFormat, DepthRule kRule>
int RasterizeWith(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                  uint32_t faceNumber, DepthBuffer& depth, CellBuffer& cells,
                  const DepthEncoding& encoding, RowRange rows);

template <DepthRule kRule>
int RasterizeWithRule(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                      uint32_t faceNumber, DepthBuffer& depth, CellBuffer& cells,
                      const DepthEncoding& encoding, RowRange rows) {
  switch (encoding.format) {
    case DepthFormat::kLinearZ:
      return RasterizeWith<DepthFormat::kLinearZ, kRule>(a, b, c, faceNumber, depth, cells,
                                                         encoding, rows);
    case DepthFormat::kFixed16InverseZ:
      return RasterizeWith<DepthFormat::kFixed16InverseZ, kRule>(a, b, c, faceNumber, depth, cells,
                                                                 encoding, rows);
    case DepthFormat::kFloatInverseZ:
      break;
  }
  return RasterizeWith<DepthFormat::kFloatInverseZ, kRule>(a, b, c, faceNumber, depth, cells,
                                                           encoding, rows);
}

}  // namespace

int RasterizeTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                      uint32_t faceNumber, DepthRule rule, DepthBuffer& depth, CellBuffer& cells,
                      const DepthEncoding& encoding, RowRange rows) {
  switch (rule) {
    case DepthRule::kOverwrite:
      return RasterizeWithRule<DepthRule::kOverwrite>(a, b, c, faceNumber, depth, cells, encoding,
                                                      rows);
    case DepthRule::kCoverOnly:
      // No depth: the format does not matter.
      return RasterizeWith<DepthFormat::kFloatInverseZ, DepthRule::kCoverOnly>(
          a, b, c, faceNumber, depth, cells, encoding, rows);
    case DepthRule::kNearestWins:
      break;
  }
  return RasterizeWithRule<DepthRule::kNearestWins>(a, b, c, faceNumber, depth, cells, encoding,
                                                    rows);
}

namespace {

template <DepthFormat kFormat, DepthRule kRule>
int RasterizeWith(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                  uint32_t faceNumber, DepthBuffer& depth, CellBuffer& cells,
                  const DepthEncoding& encoding, RowRange rows) {
  // Step 1: the cells whose samples the bounding box holds; most triangles
  // of a fine mesh hold none and stop here.
  int col0 = 0, col1 = 0, row0 = 0, row1 = 0;
  SampleRange(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), cells.WidthCells(), col0, col1);
  if (col0 > col1) return 0;
  SampleRange(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), cells.HeightCells(), row0,
              row1);
  row0 = std::max(row0, rows.first);
  row1 = std::min(row1, rows.end - 1);
  if (row0 > row1) return 0;

  // Step 2: orient clockwise on screen (positive area); drop empty triangles.
  const auto [v0, v1, v2, area] = OrientClockwise(a, b, c);
  if (area == 0) return 0;

  // Step 3: edge functions at the first sample, stepped per cell.
  const int64_t originX = int64_t{col0} * kFixedOne + kFixedHalf;
  const int64_t originY = int64_t{row0} * kFixedOne + kFixedHalf;
  const EdgeFunction e12 = MakeEdgeFunction(*v1, *v2, originX, originY);  // weight of v0
  const EdgeFunction e20 = MakeEdgeFunction(*v2, *v0, originX, originY);  // weight of v1
  const EdgeFunction e01 = MakeEdgeFunction(*v0, *v1, originX, originY);  // weight of v2
  // 1/z is linear in screen space: w = sum of edge weights times vertex w / area.
  const DepthInterpolator<kFormat> interpolate(*v0, *v1, *v2, area, encoding);

  // Step 4: visit samples; write the nearest (or latest) surface.
  int written = 0;
  int64_t row12 = e12.atOrigin, row20 = e20.atOrigin, row01 = e01.atOrigin;
  auto& faces = cells.FaceNumbers();
  for (int row = row0; row <= row1; ++row) {
    int64_t w12 = row12, w20 = row20, w01 = row01;
    size_t index = cells.Index(col0, row);
    for (int col = col0; col <= col1; ++col, ++index) {
      if ((w12 | w20 | w01) >= 0) {
        if constexpr (kRule == DepthRule::kCoverOnly) {
          faces[index] = faceNumber;
          ++written;
        } else {
          // The fill-rule bias (1 unit in 2^16 per cell^2) is negligible in the weights.
          const float w = interpolate(w12, w20, w01);
          float& stored = depth.At(index);
          const bool wins = kRule == DepthRule::kOverwrite || w > stored ||
                            (w == stored && faceNumber < faces[index]);
          if (wins) {
            stored = w;
            faces[index] = faceNumber;
            ++written;
          }
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

}  // namespace

int RasterizeTriangleScanline(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                              uint32_t faceNumber, DepthRule rule, DepthBuffer& depth,
                              CellBuffer& cells) {
  struct Point {
    float u, v, w;
  };
  // Step 1: float positions in cells, sorted top to bottom.
  Point p[3] = {{a.x / 256.0F, a.y / 256.0F, a.w},
                {b.x / 256.0F, b.y / 256.0F, b.w},
                {c.x / 256.0F, c.y / 256.0F, c.w}};
  std::sort(std::begin(p), std::end(p), [](const Point& l, const Point& r) { return l.v < r.v; });
  const float height = p[2].v - p[0].v;
  if (!(height > 0.0F)) return 0;
  // Step 2: per row, x and w on the long edge (0-2) and the short ones (0-1, 1-2).
  const float longDu = (p[2].u - p[0].u) / height, longDw = (p[2].w - p[0].w) / height;
  int written = 0;
  auto& faces = cells.FaceNumbers();
  const int firstRow = std::max(0, static_cast<int>(std::ceil(p[0].v - 0.5F)));
  const int lastRow =
      std::min(cells.HeightCells() - 1, static_cast<int>(std::ceil(p[2].v - 0.5F)) - 1);
  float longU = p[0].u + (firstRow + 0.5F - p[0].v) * longDu;
  float longW = p[0].w + (firstRow + 0.5F - p[0].v) * longDw;
  for (int row = firstRow; row <= lastRow; ++row, longU += longDu, longW += longDw) {
    const float y = row + 0.5F;
    const Point& s0 = y < p[1].v ? p[0] : p[1];
    const Point& s1 = y < p[1].v ? p[1] : p[2];
    const float span = s1.v - s0.v;
    if (!(span > 0.0F)) continue;
    const float t = (y - s0.v) / span;
    float leftU = longU, leftW = longW;
    float rightU = s0.u + t * (s1.u - s0.u), rightW = s0.w + t * (s1.w - s0.w);
    if (leftU > rightU) {
      std::swap(leftU, rightU);
      std::swap(leftW, rightW);
    }
    // Step 3: the span's samples, w stepped along the row.
    const int firstCol = std::max(0, static_cast<int>(std::ceil(leftU - 0.5F)));
    const int lastCol =
        std::min(cells.WidthCells() - 1, static_cast<int>(std::ceil(rightU - 0.5F)) - 1);
    const float dw = rightU > leftU ? (rightW - leftW) / (rightU - leftU) : 0.0F;
    float w = leftW + (firstCol + 0.5F - leftU) * dw;
    size_t index = cells.Index(std::max(0, firstCol), row);
    for (int col = firstCol; col <= lastCol; ++col, ++index, w += dw) {
      if (rule == DepthRule::kCoverOnly) {
        faces[index] = faceNumber;
        ++written;
        continue;
      }
      float& stored = depth.At(index);
      if (rule == DepthRule::kOverwrite || w > stored ||
          (w == stored && faceNumber < faces[index])) {
        stored = w;
        faces[index] = faceNumber;
        ++written;
      }
    }
  }
  return written;
}

}  // namespace termshade
