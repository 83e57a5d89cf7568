#include "raster/LineRasterizer.h"

#include <algorithm>
#include <cmath>

namespace termshade {
namespace {

void Plot(int col, int row, float w, char glyph, uint32_t faceNumber, int16_t level,
          DepthBuffer& depth, CellBuffer& cells) {
  if (col < 0 || row < 0 || col >= cells.WidthCells() || row >= cells.HeightCells()) return;
  const size_t index = cells.Index(col, row);
  cells.Glyphs()[index] = glyph;
  cells.FaceNumbers()[index] = faceNumber;
  cells.Levels()[index] = level;
  depth.At(index) = w;
}

}  // namespace

char LineGlyph(double duCells, double dvCells, double cellAspect) {
  const double across = std::fabs(duCells);
  const double up = std::fabs(dvCells * cellAspect);
  // tan(22.5 deg) and tan(67.5 deg) split the circle into the four characters.
  if (up <= 0.41421356 * across) return '-';
  if (up >= 2.41421356 * across) return '|';
  return (duCells > 0) == (dvCells < 0) ? '/' : '\\';
}

void DrawLine(const CellPoint& a, const CellPoint& b, double cellAspect, uint32_t faceNumber,
              int16_t level, DepthBuffer& depth, CellBuffer& cells) {
  const double du = b.u - a.u, dv = b.v - a.v;
  const char glyph = LineGlyph(du, dv, cellAspect);
  const bool alongColumns = std::fabs(du) >= std::fabs(dv);
  const double major0 = alongColumns ? a.u : a.v, major1 = alongColumns ? b.u : b.v;
  const double low = std::min(major0, major1), high = std::max(major0, major1);
  if (!(high > low)) {  // a point (both ends in one place): no direction to step along
    Plot(static_cast<int>(std::floor(a.u)), static_cast<int>(std::floor(a.v)),
         static_cast<float>(a.w), glyph, faceNumber, level, depth, cells);
    return;
  }
  const int limit = alongColumns ? cells.WidthCells() : cells.HeightCells();
  // Cells whose center (k + 0.5) the segment passes along its major axis.
  const int first = std::max(0, static_cast<int>(std::ceil(low - 0.5)));
  const int last = std::min(limit - 1, static_cast<int>(std::floor(high - 0.5)));
  if (first > last) {
    if (high - low < 1.0) {  // shorter than a cell: mark the cell of its midpoint
      Plot(static_cast<int>(std::floor(0.5 * (a.u + b.u))),
           static_cast<int>(std::floor(0.5 * (a.v + b.v))), static_cast<float>(0.5 * (a.w + b.w)),
           glyph, faceNumber, level, depth, cells);
    }
    return;
  }
  for (int k = first; k <= last; ++k) {
    const double t = (k + 0.5 - major0) / (major1 - major0);
    const double minor = alongColumns ? a.v + t * dv : a.u + t * du;
    const int minorCell = static_cast<int>(std::floor(minor));
    const float w = static_cast<float>(a.w + t * (b.w - a.w));
    if (alongColumns) {
      Plot(k, minorCell, w, glyph, faceNumber, level, depth, cells);
    } else {
      Plot(minorCell, k, w, glyph, faceNumber, level, depth, cells);
    }
  }
}

}  // namespace termshade
