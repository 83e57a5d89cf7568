#include "raster/VertexStage.h"

#include <algorithm>
#include <cmath>

#include "geometry/FixedRange.h"
#include "raster/FixedPoint.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace termshade {
namespace {

// The per-frame constants of the projection and the conservative inside test.
struct StageConstants {
  Mat4 m;
  double d, vScale, cx, cy;
  double nearZ;           ///< twice the near distance: surely in front
  double xLimit, yLimit;  ///< half the guard band: surely inside it
};

StageConstants MakeConstants(const Mat4& eyeFromWorld, const Projection& proj,
                             const ViewClipPlanes& planes) {
  return {eyeFromWorld,
          proj.d,
          proj.d / proj.cellAspect,
          proj.cx,
          proj.cy,
          2.0 * -planes[0].offset,
          0.5 * (kClipRangeCells - proj.cx),
          0.5 * (kClipRangeCells - proj.cy)};
}

RasterVertex ToRaster(const CellPoint& p) {
  return {SnapToFixed(p.u), SnapToFixed(p.v), static_cast<float>(p.w)};
}

// The same transform and projection in float (the measured variant).
Vec3 TransformInFloat(const Mat4& eyeFromWorld, Vec3 pWorld) {
  const auto& m = eyeFromWorld.m;
  const auto x = static_cast<float>(pWorld.x), y = static_cast<float>(pWorld.y),
             z = static_cast<float>(pWorld.z);
  auto row = [&](size_t r) {
    return static_cast<float>(m[r * 4]) * x + static_cast<float>(m[r * 4 + 1]) * y +
           static_cast<float>(m[r * 4 + 2]) * z + static_cast<float>(m[r * 4 + 3]);
  };
  return {row(0), row(1), row(2)};
}

RasterVertex ProjectInFloat(const Projection& proj, Vec3 pEye) {
  const float w = -1.0F / static_cast<float>(pEye.z);
  const float u =
      static_cast<float>(proj.cx) + static_cast<float>(proj.d) * static_cast<float>(pEye.x) * w;
  const float v = static_cast<float>(proj.cy) -
                  static_cast<float>(proj.d / proj.cellAspect) * static_cast<float>(pEye.y) * w;
  return {SnapToFixed(u), SnapToFixed(v), w};
}

// One vertex: in view (far from every clip plane) it is projected here; the
// others get exact out-codes and are clipped per triangle later.
template <bool kFloatGeometry>
float ProjectOne(const StageConstants& k, const Projection& proj, const ViewClipPlanes& planes,
                 Vec3 pWorld, size_t i, const VertexStageOutput& out) {
  const Vec3 pEye = kFloatGeometry ? TransformInFloat(k.m, pWorld) : TransformPoint(k.m, pWorld);
  if (out.eyeZ != nullptr) out.eyeZ[i] = pEye.z;
  // ProjectToCell, inlined: u = cx + d x w, v = cy - d y w / a with w = -1/z.
  const double w = -1.0 / pEye.z;
  const double xCells = k.d * pEye.x * w, yCells = k.vScale * pEye.y * w;
  if (pEye.z <= -k.nearZ && std::fabs(xCells) <= k.xLimit && std::fabs(yCells) <= k.yLimit) {
    out.outCodes[i] = 0;
    out.raster[i] = kFloatGeometry
                        ? ProjectInFloat(proj, pEye)
                        : RasterVertex{SnapToFixed(k.cx + xCells), SnapToFixed(k.cy - yCells),
                                       static_cast<float>(w)};
    return out.raster[i].w;
  }
  const unsigned code = OutCode(planes, pEye);
  out.outCodes[i] = static_cast<uint8_t>(code);
  out.raster[i] = code == 0 ? ToRaster(ProjectToCell(proj, pEye)) : RasterVertex{};
  return out.raster[i].w;
}

#if defined(__SSE2__)
// Two vertices at once, from `start` while both of a pair are surely in
// view; returns where it stopped. The same operations in the same order as
// ProjectOne<false>, so the results are bit for bit the same.
size_t ProjectPairs(const StageConstants& k, std::span<const Vec3> vertices, size_t start,
                    const VertexStageOutput& out, float& maxW) {
  const __m128d m0 = _mm_set1_pd(k.m.m[0]), m1 = _mm_set1_pd(k.m.m[1]), m2 = _mm_set1_pd(k.m.m[2]),
                m3 = _mm_set1_pd(k.m.m[3]), m4 = _mm_set1_pd(k.m.m[4]), m5 = _mm_set1_pd(k.m.m[5]),
                m6 = _mm_set1_pd(k.m.m[6]), m7 = _mm_set1_pd(k.m.m[7]), m8 = _mm_set1_pd(k.m.m[8]),
                m9 = _mm_set1_pd(k.m.m[9]), m10 = _mm_set1_pd(k.m.m[10]),
                m11 = _mm_set1_pd(k.m.m[11]);
  const __m128d d = _mm_set1_pd(k.d), vScale = _mm_set1_pd(k.vScale), cx = _mm_set1_pd(k.cx),
                cy = _mm_set1_pd(k.cy), minusOne = _mm_set1_pd(-1.0),
                minusNear = _mm_set1_pd(-k.nearZ), xLimit = _mm_set1_pd(k.xLimit),
                yLimit = _mm_set1_pd(k.yLimit), fixedOne = _mm_set1_pd(kFixedOne),
                half = _mm_set1_pd(0.5), signBit = _mm_set1_pd(-0.0);
  size_t i = start;
  for (; i + 1 < vertices.size(); i += 2) {
    const Vec3& a = vertices[i];
    const Vec3& b = vertices[i + 1];
    const __m128d x = _mm_set_pd(b.x, a.x), y = _mm_set_pd(b.y, a.y), z = _mm_set_pd(b.z, a.z);
    auto row = [&](__m128d r0, __m128d r1, __m128d r2, __m128d r3) {
      return _mm_add_pd(
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(r0, x), _mm_mul_pd(r1, y)), _mm_mul_pd(r2, z)), r3);
    };
    const __m128d ex = row(m0, m1, m2, m3), ey = row(m4, m5, m6, m7), ez = row(m8, m9, m10, m11);
    const __m128d w = _mm_div_pd(minusOne, ez);
    const __m128d xCells = _mm_mul_pd(_mm_mul_pd(d, ex), w);
    const __m128d yCells = _mm_mul_pd(_mm_mul_pd(vScale, ey), w);
    const __m128d inside =
        _mm_and_pd(_mm_cmple_pd(ez, minusNear),
                   _mm_and_pd(_mm_cmple_pd(_mm_andnot_pd(signBit, xCells), xLimit),
                              _mm_cmple_pd(_mm_andnot_pd(signBit, yCells), yLimit)));
    if (_mm_movemask_pd(inside) != 3) break;  // rare: the caller takes the exact path
    if (out.eyeZ != nullptr) _mm_storeu_pd(out.eyeZ + i, ez);
    // SnapToFixed: scale, add 0.5 away from zero, truncate.
    auto snap = [&](__m128d cells) {
      const __m128d scaled = _mm_mul_pd(cells, fixedOne);
      return _mm_cvttpd_epi32(_mm_add_pd(scaled, _mm_or_pd(half, _mm_and_pd(scaled, signBit))));
    };
    alignas(16) int32_t us[4], vs[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(us), snap(_mm_add_pd(cx, xCells)));
    _mm_store_si128(reinterpret_cast<__m128i*>(vs), snap(_mm_sub_pd(cy, yCells)));
    alignas(16) double ws[2];
    _mm_store_pd(ws, w);
    for (size_t j = 0; j < 2; ++j) {
      out.outCodes[i + j] = 0;
      out.raster[i + j] = {us[j], vs[j], static_cast<float>(ws[j])};
      maxW = std::max(maxW, out.raster[i + j].w);
    }
  }
  return i;
}
#endif

}  // namespace

float ProjectVertices(std::span<const Vec3> verticesWorld, const Mat4& eyeFromWorld,
                      const Projection& proj, const ViewClipPlanes& planes, bool floatGeometry,
                      const VertexStageOutput& out) {
  const StageConstants k = MakeConstants(eyeFromWorld, proj, planes);
  float maxW = 0.0F;
  size_t i = 0;
  if (floatGeometry) {
    for (; i < verticesWorld.size(); ++i) {
      maxW = std::max(maxW, ProjectOne<true>(k, proj, planes, verticesWorld[i], i, out));
    }
    return maxW;
  }
#if defined(__SSE2__)
  // Pairs while both are in view; a pair that is not takes the exact path,
  // then pairs go on after it.
  while (i + 1 < verticesWorld.size()) {
    i = ProjectPairs(k, verticesWorld, i, out, maxW);
    if (i + 1 >= verticesWorld.size()) break;
    for (const size_t end = i + 2; i < end; ++i) {
      maxW = std::max(maxW, ProjectOne<false>(k, proj, planes, verticesWorld[i], i, out));
    }
  }
#endif
  for (; i < verticesWorld.size(); ++i) {
    maxW = std::max(maxW, ProjectOne<false>(k, proj, planes, verticesWorld[i], i, out));
  }
  return maxW;
}

}  // namespace termshade
