#include "raster/SampledRasterizer.h"

#include <algorithm>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "raster/EdgeFunction.h"
#include "raster/FixedPoint.h"

namespace termshade {
namespace {

using Edge = EdgeFunction;

// Samples s (centers s * 256 + 128) in [low, high], clipped to [0, limit).
void SampleRange(int32_t low, int32_t high, int limit, int& first, int& last) {
  first = std::max(0, (low - kFixedHalf + kFixedOne - 1) >> kSubCellBits);
  last = std::min(limit - 1, (high - kFixedHalf) >> kSubCellBits);
}

// A triangle's edges from an origin sample and its depth weights, as
// RasterizeTriangle sets them up (v0, v1, v2 clockwise, area > 0).
struct Setup {
  Edge e12, e20, e01;  // weights of v0, v1, v2
  float k0, k1, k2;    // as DepthInterpolator<kFloatInverseZ>
};

inline __attribute__((always_inline)) Setup MakeSetup(const RasterVertex& v0,
                                                      const RasterVertex& v1,
                                                      const RasterVertex& v2, int64_t area,
                                                      int64_t originX, int64_t originY) {
  const float invArea = 1.0F / static_cast<float>(area);
  return {MakeEdgeFunction(v1, v2, originX, originY),
          MakeEdgeFunction(v2, v0, originX, originY),
          MakeEdgeFunction(v0, v1, originX, originY),
          v0.w * invArea,
          v1.w * invArea,
          v2.w * invArea};
}

// One covered sample by the rule: the same float operations in the same order
// as RasterizeTriangle.
template <DepthRule kRule, typename Lane>
void StoreSample(const Setup& t, Lane w12, Lane w20, Lane w01, uint32_t faceNumber, uint32_t& face,
                 float& stored) {
  if constexpr (kRule == DepthRule::kCoverOnly) {
    face = faceNumber;
  } else {
    const float w = static_cast<float>(w12) * t.k0 + static_cast<float>(w20) * t.k1 +
                    static_cast<float>(w01) * t.k2;
    if (kRule == DepthRule::kOverwrite || w > stored || (w == stored && faceNumber < face)) {
      stored = w;
      face = faceNumber;
    }
  }
}

// Four lanes (GCC vector extensions; SSE2 registers on x86-64): a cell's
// samples in one or two of them, the rest padding.
typedef int32_t Int4 __attribute__((vector_size(16)));
typedef float Float4 __attribute__((vector_size(16)));

bool AnyLane(Int4 mask) {
#if defined(__SSE2__)
  return _mm_movemask_epi8(reinterpret_cast<__m128i>(mask)) != 0;
#else
  return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
#endif
}

typedef uint32_t UInt4 __attribute__((vector_size(16)));
typedef uint32_t UInt8 __attribute__((vector_size(32)));

// Vector h's lanes: the column and row of each sample in the cell, 0 for padding.
template <int K, int M>
UInt4 LaneColumns(int h) {
  UInt4 lanes{};
  for (int l = 0; l < 4; ++l) {
    lanes[l] = 4 * h + l < K * M ? static_cast<uint32_t>((4 * h + l) % K) : 0U;
  }
  return lanes;
}
template <int K, int M>
UInt4 LaneRows(int h) {
  UInt4 lanes{};
  for (int l = 0; l < 4; ++l) {
    lanes[l] = 4 * h + l < K * M ? static_cast<uint32_t>((4 * h + l) / K) : 0U;
  }
  return lanes;
}

// The offsets of vector h's four lanes from the cell's first sample: i stepX +
// j stepY in 32 bits (wrapping as the 64-bit value's low half does), built in
// registers (lane by lane stores read back as a vector stall on store forwarding).
template <int K, int M>
Int4 LaneOffsets(const Edge& e, int h) {
  const auto stepX = static_cast<uint32_t>(e.stepX), stepY = static_cast<uint32_t>(e.stepY);
  return reinterpret_cast<Int4>(LaneColumns<K, M>(h) * stepX + LaneRows<K, M>(h) * stepY);
}

// DrawCells with 32-bit edge values, four samples of a cell at a time: the
// same integers, conversions and float operations, lane by lane.
template <int K, int M, DepthRule kRule>
void DrawCellsVector(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                     int64_t area, uint32_t faceNumber, SampleFrame& frame, int cellCol0,
                     int cellCol1, int cellRow0, int cellRow1) {
  constexpr int kCount = K * M;
  constexpr int kVectors = (kCount + 3) / 4;
  const int64_t originX = int64_t{cellCol0} * K * kFixedOne + kFixedHalf;
  const int64_t originY = int64_t{cellRow0} * M * kFixedOne + kFixedHalf;
  const Setup t = MakeSetup(v0, v1, v2, area, originX, originY);
  const Edge &e12 = t.e12, &e20 = t.e20, &e01 = t.e01;
  Int4 o12[kVectors], o20[kVectors], o01[kVectors], valid[kVectors];
  for (int h = 0; h < kVectors; ++h) {
    o12[h] = LaneOffsets<K, M>(e12, h);
    o20[h] = LaneOffsets<K, M>(e20, h);
    o01[h] = LaneOffsets<K, M>(e01, h);
    for (int l = 0; l < 4; ++l) valid[h][l] = 4 * h + l < kCount ? -1 : 0;
  }
  const auto face = static_cast<int32_t>(faceNumber);
  uint32_t* const faces = frame.FaceData();
  float* const depth = frame.DepthData();
  uint8_t* const touched = frame.TouchedData();
  const size_t width = static_cast<size_t>(frame.WidthCells());
  int64_t row12 = e12.atOrigin, row20 = e20.atOrigin, row01 = e01.atOrigin;
  for (int row = cellRow0; row <= cellRow1; ++row) {
    int64_t b12 = row12, b20 = row20, b01 = row01;
    size_t cell = row * width + cellCol0;
    for (int col = cellCol0; col <= cellCol1;
         ++col, ++cell, b12 += K * e12.stepX, b20 += K * e20.stepX, b01 += K * e01.stepX) {
      // Step 1: the covered samples, four lanes at a time (branch-free: for
      // small triangles a test of the cell's corners first costs more than it saves).
      const auto l12 = static_cast<int32_t>(b12), l20 = static_cast<int32_t>(b20),
                 l01 = static_cast<int32_t>(b01);
      Int4 covered[kVectors];
      Int4 anyLanes{};
      for (int h = 0; h < kVectors; ++h) {
        covered[h] = valid[h] & (((l12 + o12[h]) | (l20 + o20[h]) | (l01 + o01[h])) >= 0);
        anyLanes |= covered[h];
      }
      const bool any = AnyLane(anyLanes);
      if (!any) continue;
      // Step 2: the covered samples, by the rule (padding lanes written back unchanged;
      // a cell touched first now starts as background).
      const Int4 fresh = touched[cell] == 0 ? valid[0] : Int4{};
      if (kRule == DepthRule::kCoverOnly && touched[cell] == 0) {
        std::memset(depth + cell * kCount, 0, kCount * sizeof(float));
      }
      touched[cell] = 1;
      for (int h = 0; h < kVectors; ++h) {
        uint32_t* const laneFaces = faces + cell * kCount + 4 * h;
        Int4 storedFaces;
        std::memcpy(&storedFaces, laneFaces, sizeof storedFaces);
        const Int4 cleared = fresh & valid[h];
        storedFaces &= ~cleared;
        if constexpr (kRule == DepthRule::kCoverOnly) {
          storedFaces = covered[h] ? face : storedFaces;
        } else {
          float* const laneDepth = depth + cell * kCount + 4 * h;
          Float4 stored;
          std::memcpy(&stored, laneDepth, sizeof stored);
          stored = cleared ? Float4{} : stored;
          const Float4 w = __builtin_convertvector(l12 + o12[h], Float4) * t.k0 +
                           __builtin_convertvector(l20 + o20[h], Float4) * t.k1 +
                           __builtin_convertvector(l01 + o01[h], Float4) * t.k2;
          Int4 wins = covered[h];
          if constexpr (kRule == DepthRule::kNearestWins) {
            wins &= (w > stored) | ((w == stored) & (face < storedFaces));
          }
          stored = wins ? w : stored;
          storedFaces = wins ? face : storedFaces;
          std::memcpy(laneDepth, &stored, sizeof stored);
        }
        std::memcpy(laneFaces, &storedFaces, sizeof storedFaces);
      }
    }
    row12 += M * e12.stepY;
    row20 += M * e20.stepY;
    row01 += M * e01.stepY;
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
#define TERMSHADE_WIDE_CELLS 1
// DrawCellsVector for 8 (or 6) samples a cell with AVX2: a cell's samples in one
// register of eight lanes (the same integers, conversions and float
// operations lane by lane; no FMA, so products and sums round as before).
typedef int32_t Int8 __attribute__((vector_size(32)));
typedef float Float8 __attribute__((vector_size(32)));
typedef long long Long4
    __attribute__((vector_size(32)));  // NOLINT(google-runtime-int): ptest's type

// Edge e's values at eight samples (columns i, rows j from the origin sample).
__attribute__((target("avx2"), always_inline)) inline Int8 LaneValues(const Edge& e, UInt8 i,
                                                                      UInt8 j) {
  return reinterpret_cast<Int8>(i * static_cast<uint32_t>(e.stepX) +
                                j * static_cast<uint32_t>(e.stepY) +
                                static_cast<uint32_t>(e.atOrigin));
}

template <int K, int M, DepthRule kRule>
__attribute__((target("avx2"))) void DrawCellsWide(const RasterVertex& v0, const RasterVertex& v1,
                                                   const RasterVertex& v2, int64_t area,
                                                   uint32_t faceNumber, SampleFrame& frame,
                                                   int cellCol0, int cellCol1, int cellRow0,
                                                   int cellRow1) {
  constexpr int kCount = K * M;  // 8, or 6 with two padding lanes
  static_assert(kCount == 8 || kCount == 6);
  const int64_t originX = int64_t{cellCol0} * K * kFixedOne + kFixedHalf;
  const int64_t originY = int64_t{cellRow0} * M * kFixedOne + kFixedHalf;
  const Setup t = MakeSetup(v0, v1, v2, area, originX, originY);
  const Edge &e12 = t.e12, &e20 = t.e20, &e01 = t.e01;
  // Each lane's offset from the cell's first sample: i stepX + j stepY (32 bits, wrapping).
  // Padding lanes repeat the first samples (their values stay in range) and
  // are never covered; they overlap the next cell's first samples, which
  // they write back unchanged.
  Int8 columns, rows, valid;
  for (int l = 0; l < 8; ++l) {
    columns[l] = (l % kCount) % K;
    rows[l] = (l % kCount) / K;
    valid[l] = l < kCount ? -1 : 0;
  }
  const UInt8 i = reinterpret_cast<UInt8>(columns), j = reinterpret_cast<UInt8>(rows);
  // The lanes' edge values at the box's first cell, and their steps a cell across and down
  // (32 bits, wrapping as the 64-bit values' low halves do).
  const auto across = [](const Edge& e) {
    return static_cast<int32_t>(static_cast<uint32_t>(e.stepX) * K);
  };
  const auto down = [](const Edge& e) {
    return static_cast<int32_t>(static_cast<uint32_t>(e.stepY) * M);
  };
  const int32_t across12 = across(e12), across20 = across(e20), across01 = across(e01);
  const int32_t down12 = down(e12), down20 = down(e20), down01 = down(e01);
  const auto face = static_cast<int32_t>(faceNumber);
  uint32_t* const faces = frame.FaceData();
  float* const depth = frame.DepthData();
  uint8_t* const touched = frame.TouchedData();
  const size_t width = static_cast<size_t>(frame.WidthCells());
  Int8 row12 = LaneValues(e12, i, j), row20 = LaneValues(e20, i, j), row01 = LaneValues(e01, i, j);
  for (int row = cellRow0; row <= cellRow1; ++row) {
    Int8 w12 = row12, w20 = row20, w01 = row01;
    size_t cell = row * width + cellCol0;
    for (int col = cellCol0; col <= cellCol1;
         ++col, ++cell, w12 += across12, w20 += across20, w01 += across01) {
      // Step 1: the covered samples (sign bits clear in all three).
      const Int8 covered = valid & ((w12 | w20 | w01) > -1);
      // Step 2: by the rule, without branches (which the cells' coverage makes
      // unpredictable; measured after another mode's frame, 9% quicker, 5%
      // slower when the same frames repeat): a cell no sample reaches is
      // written back as it was, or as background if untouched (and stays untouched).
      const bool any = __builtin_ia32_ptestz256(reinterpret_cast<Long4>(covered),
                                                reinterpret_cast<Long4>(covered)) == 0;
      const uint8_t wasTouched = touched[cell];
      const Int8 kept = (Int8{} - static_cast<int32_t>(wasTouched)) | ~valid;  // flags: 0 or 1
      touched[cell] = wasTouched | static_cast<uint8_t>(any);
      uint32_t* const cellFaces = faces + cell * kCount;
      float* const cellDepth = depth + cell * kCount;
      Int8 storedFaces;
      std::memcpy(&storedFaces, cellFaces, sizeof storedFaces);
      storedFaces &= kept;
      if constexpr (kRule == DepthRule::kCoverOnly) {
        Int8 storedDepth;
        std::memcpy(&storedDepth, cellDepth, sizeof storedDepth);
        storedDepth &= kept;
        std::memcpy(cellDepth, &storedDepth, sizeof storedDepth);
        storedFaces = covered ? face : storedFaces;
      } else {
        Int8 storedBits;
        std::memcpy(&storedBits, cellDepth, sizeof storedBits);
        const auto stored = reinterpret_cast<Float8>(storedBits & kept);
        const Float8 w = __builtin_convertvector(w12, Float8) * t.k0 +
                         __builtin_convertvector(w20, Float8) * t.k1 +
                         __builtin_convertvector(w01, Float8) * t.k2;
        Int8 wins = covered;
        if constexpr (kRule == DepthRule::kNearestWins) {
          wins &= (w > stored) | ((w == stored) & (face < storedFaces));
        }
        const Float8 nearest = wins ? w : stored;
        storedFaces = wins ? face : storedFaces;
        std::memcpy(cellDepth, &nearest, sizeof nearest);
      }
      std::memcpy(cellFaces, &storedFaces, sizeof storedFaces);
    }
    row12 += down12;
    row20 += down20;
    row01 += down01;
  }
}
#endif

// RasterizeTriangle's step 4 sample by sample over the box, each sample
// written at its place in the cell-major frame: small triangles, whose box
// holds few samples.
template <int K, int M, DepthRule kRule>
void DrawSamples(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                 int64_t area, uint32_t faceNumber, SampleFrame& frame, int col0, int col1,
                 int row0, int row1) {
  constexpr int kCount = K * M;
  const int64_t originX = int64_t{col0} * kFixedOne + kFixedHalf;
  const int64_t originY = int64_t{row0} * kFixedOne + kFixedHalf;
  const Setup t = MakeSetup(v0, v1, v2, area, originX, originY);
  const Edge &e12 = t.e12, &e20 = t.e20, &e01 = t.e01;
  uint32_t* const faces = frame.FaceData();
  float* const depth = frame.DepthData();
  const size_t width = static_cast<size_t>(frame.WidthCells());
  int64_t row12 = e12.atOrigin, row20 = e20.atOrigin, row01 = e01.atOrigin;
  for (int row = row0; row <= row1; ++row) {
    int64_t w12 = row12, w20 = row20, w01 = row01;
    const size_t rowCells = static_cast<size_t>(row / M) * width;
    const int laneRow = (row % M) * K;
    for (int col = col0; col <= col1; ++col) {
      if ((w12 | w20 | w01) >= 0) {
        const size_t cell = rowCells + static_cast<size_t>(col / K);
        const size_t index = cell * kCount + laneRow + col % K;
        frame.Touch(cell);
        StoreSample<kRule>(t, w12, w20, w01, faceNumber, faces[index], depth[index]);
      }
      w12 += e12.stepX;
      w20 += e20.stepX;
      w01 += e01.stepX;
    }
    row12 += e12.stepY;
    row20 += e20.stepY;
    row01 += e01.stepY;
  }
}

template <int K, int M, DepthRule kRule, bool kWide>
void DrawTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                  uint32_t faceNumber, SampleFrame& frame) {
  // Step 1: the samples the bounding box holds, as RasterizeTriangle finds them.
  const int32_t minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
  int col0 = 0, col1 = 0, row0 = 0, row1 = 0;
  SampleRange(minX, maxX, frame.WidthCells() * K, col0, col1);
  if (col0 > col1) return;
  const int32_t minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
  SampleRange(minY, maxY, frame.HeightCells() * M, row0, row1);
  if (row0 > row1) return;
  // Step 2: orient clockwise on screen; drop empty triangles.
  const auto [v0, v1, v2, area] = OrientClockwise(a, b, c);
  if (area == 0) return;
  // Step 3: 32-bit lanes when |edge| <= 2 extent (extent + a cell) + 1 < 2^31
  // for every sample of the cells the box touches.
  const int64_t extent = std::max(int64_t{maxX} - minX, int64_t{maxY} - minY);
  const int64_t reach = extent + int64_t{std::max(K, M)} * kFixedOne;
  // 1x2 cells sample by sample; the rest cell by cell where 32 bits hold every
  // edge value, else (huge triangles) sample by sample. (Measured on
  // sphere_cone at 2x4: cell by cell is quicker than sample by sample for
  // small boxes too, once a cell touched first starts as background in registers.)
  const bool fits32 = 2 * extent * reach + 1 < (int64_t{1} << 31) - 1;
  if (K * M <= 2 || !fits32) {
    DrawSamples<K, M, kRule>(*v0, *v1, *v2, area, faceNumber, frame, col0, col1, row0, row1);
  } else {
#if defined(TERMSHADE_WIDE_CELLS)
    if constexpr (kWide && (K * M == 8 || K * M == 6)) {
      DrawCellsWide<K, M, kRule>(*v0, *v1, *v2, area, faceNumber, frame, col0 / K, col1 / K,
                                 row0 / M, row1 / M);
      return;
    }
#endif
    DrawCellsVector<K, M, kRule>(*v0, *v1, *v2, area, faceNumber, frame, col0 / K, col1 / K,
                                 row0 / M, row1 / M);
  }
}

template <int K, int M, bool kWide>
SampledRasterizer::DrawFunction ForRule(DepthRule rule) {
  switch (rule) {
    case DepthRule::kCoverOnly:
      return DrawTriangle<K, M, DepthRule::kCoverOnly, kWide>;
    case DepthRule::kOverwrite:
      return DrawTriangle<K, M, DepthRule::kOverwrite, kWide>;
    case DepthRule::kNearestWins:
      break;
  }
  return DrawTriangle<K, M, DepthRule::kNearestWins, kWide>;
}

template <int K, int M>
SampledRasterizer::DrawFunction ForRule(DepthRule rule, bool wide) {
  return wide ? ForRule<K, M, true>(rule) : ForRule<K, M, false>(rule);
}

}  // namespace

bool SampledRasterizer::Supports(SampleGrid grid) {
  return grid == SampleGrid{1, 2} || grid == SampleGrid{2, 2} || grid == SampleGrid{2, 3} ||
         grid == SampleGrid{2, 4};
}

bool SampledRasterizer::WideAvailable() {
#if defined(TERMSHADE_WIDE_CELLS)
  return __builtin_cpu_supports("avx2") != 0;
#else
  return false;
#endif
}

SampledRasterizer::SampledRasterizer(SampleFrame& frame, DepthRule rule, bool wide)
    : frame_(frame) {
  wide = wide && WideAvailable();
  const SampleGrid g = frame.Grid();
  if (g == SampleGrid{1, 2}) draw_ = ForRule<1, 2, false>(rule);
  if (g == SampleGrid{2, 2}) draw_ = ForRule<2, 2, false>(rule);
  if (g == SampleGrid{2, 3}) draw_ = ForRule<2, 3>(rule, wide);
  if (g == SampleGrid{2, 4}) draw_ = ForRule<2, 4>(rule, wide);
}

}  // namespace termshade
