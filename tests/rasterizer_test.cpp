// The rasterizer by exact coverage counts: sample centers, top-left rule,
// watertight shared edges (SPEC 5).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "raster/FixedPoint.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {
namespace {

using Triangle = std::array<RasterVertex, 3>;

constexpr int kWidth = 37;
constexpr int kHeight = 23;

// How many triangles cover each cell's sample.
std::vector<int> CoverageCounts(const std::vector<Triangle>& triangles, int width = kWidth,
                                int height = kHeight) {
  std::vector<int> counts(static_cast<size_t>(width) * height, 0);
  CellBuffer cells(width, height);
  DepthBuffer depth;
  depth.Resize(width, height);
  for (const Triangle& t : triangles) {
    cells.Clear();
    depth.Clear();
    RasterizeTriangle(t[0], t[1], t[2], 1, DepthRule::kOverwrite, depth, cells);
    for (size_t i = 0; i < counts.size(); ++i) counts[i] += cells.FaceNumbers()[i] == 1 ? 1 : 0;
  }
  return counts;
}

// Which triangle (1-based, in order) covers each sample.
CellBuffer TriangleMap(const std::vector<Triangle>& triangles) {
  CellBuffer cells(kWidth, kHeight);
  DepthBuffer depth;
  depth.Resize(kWidth, kHeight);
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    RasterizeTriangle(t[0], t[1], t[2], static_cast<uint32_t>(i + 1), DepthRule::kOverwrite, depth,
                      cells);
  }
  return cells;
}

struct GridOptions {
  double stepCells = 3.0;
  double jitterCells = 0.0;
  double rotationRadians = 0.0;
  bool flipDiagonals = false;
  int rotateVertexOrder = 0;
  double shiftCells = 0.0;
  unsigned seed = 1;
};

// A grid of quads, split into triangles, covering well beyond the view.
std::vector<Triangle> TilingMesh(const GridOptions& options) {
  const double extent = 2.0 * (kWidth + kHeight);
  const int n = static_cast<int>(std::ceil(2.0 * extent / options.stepCells));
  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> jitter(-options.jitterCells, options.jitterCells);
  const double cosR = std::cos(options.rotationRadians), sinR = std::sin(options.rotationRadians);
  std::vector<RasterVertex> grid;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      // Lattice points sit on cell centers before jitter and rotation.
      const double x = -extent + 0.5 + i * options.stepCells + jitter(random);
      const double y = -extent + 0.5 + j * options.stepCells + jitter(random);
      const double cx = 0.5 * kWidth, cy = 0.5 * kHeight;
      const double u = cx + cosR * (x - cx) - sinR * (y - cy) + options.shiftCells;
      const double v = cy + sinR * (x - cx) + cosR * (y - cy) + options.shiftCells;
      grid.push_back({SnapToFixed(u), SnapToFixed(v), 1.0F});
    }
  }
  auto at = [&](int i, int j) { return grid[static_cast<size_t>(i * (n + 1) + j)]; };
  std::vector<Triangle> triangles;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const RasterVertex a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      std::array<Triangle, 2> pair = options.flipDiagonals
                                         ? std::array<Triangle, 2>{{{a, b, d}, {b, c, d}}}
                                         : std::array<Triangle, 2>{{{a, b, c}, {a, c, d}}};
      for (Triangle t : pair) {
        std::rotate(t.begin(), t.begin() + options.rotateVertexOrder, t.end());
        triangles.push_back(t);
      }
    }
  }
  return triangles;
}

void ExpectEveryCellOnce(const std::vector<int>& counts) {
  int wrong = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] != 1) {
      ++wrong;
      ADD_FAILURE() << "cell (" << i % kWidth << ", " << i / kWidth << ") covered " << counts[i]
                    << " times";
      if (wrong > 5) return;
    }
  }
}

TEST(Rasterizer, TwoTrianglesOfARectangleCoverItsSamplesExactly) {
  // Rectangle [2, 10) x [3, 8) in cells: corners on cell boundaries.
  const RasterVertex a{SnapToFixed(2), SnapToFixed(3), 1}, b{SnapToFixed(10), SnapToFixed(3), 1},
      c{SnapToFixed(10), SnapToFixed(8), 1}, d{SnapToFixed(2), SnapToFixed(8), 1};
  const std::vector<int> counts = CoverageCounts({{a, b, c}, {a, c, d}});
  int covered = 0;
  for (int count : counts) covered += count;
  EXPECT_EQ(covered, 8 * 5);
}

TEST(Rasterizer, SamplesOnEdgesFollowTheTopLeftRule) {
  // A square whose corners are cell centers: samples on its top and left
  // edges are in, those on its bottom and right edges are out.
  const RasterVertex a{SnapToFixed(2.5), SnapToFixed(3.5), 1},
      b{SnapToFixed(6.5), SnapToFixed(3.5), 1}, c{SnapToFixed(6.5), SnapToFixed(7.5), 1},
      d{SnapToFixed(2.5), SnapToFixed(7.5), 1};
  const std::vector<int> counts = CoverageCounts({{a, b, c}, {a, c, d}});
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const bool inside = col >= 2 && col < 6 && row >= 3 && row < 7;
      EXPECT_EQ(counts[static_cast<size_t>(row * kWidth + col)], inside ? 1 : 0)
          << col << "," << row;
    }
  }
}

TEST(Rasterizer, EmptyAndDegenerateTrianglesDrawNothing) {
  const RasterVertex a{SnapToFixed(1.5), SnapToFixed(1.5), 1},
      b{SnapToFixed(9.5), SnapToFixed(5.5), 1},
      c{SnapToFixed(17.5), SnapToFixed(9.5), 1};  // collinear
  const std::vector<int> counts = CoverageCounts({{a, b, c}, {a, a, a}, {a, b, b}});
  for (int count : counts) EXPECT_EQ(count, 0);
}

TEST(Rasterizer, CoverOnlyCoversTheSameSamplesAndLeavesDepthAlone) {
  const RasterVertex a{SnapToFixed(1.2), SnapToFixed(1.7), 0.5F},
      b{SnapToFixed(30.1), SnapToFixed(4.3), 0.25F}, c{SnapToFixed(7.9), SnapToFixed(19.6), 1};
  CellBuffer overwritten(kWidth, kHeight), coverOnly(kWidth, kHeight);
  DepthBuffer depth;
  depth.Resize(kWidth, kHeight);
  depth.Clear();
  const int written = RasterizeTriangle(a, b, c, 3, DepthRule::kOverwrite, depth, overwritten);
  const int touched = [&] {
    DepthBuffer untouched;
    untouched.Resize(kWidth, kHeight);
    untouched.Clear();
    const int count = RasterizeTriangle(a, b, c, 3, DepthRule::kCoverOnly, untouched, coverOnly);
    for (int i = 0; i < kWidth * kHeight; ++i) EXPECT_EQ(untouched.At(i), 0.0F) << i;
    return count;
  }();
  EXPECT_GT(written, 100);
  EXPECT_EQ(touched, written);
  EXPECT_EQ(coverOnly.FaceNumbers(), overwritten.FaceNumbers());
}

TEST(Rasterizer, WindingDoesNotMatter) {
  const RasterVertex a{SnapToFixed(1.2), SnapToFixed(1.7), 1},
      b{SnapToFixed(20.1), SnapToFixed(4.3), 1}, c{SnapToFixed(7.9), SnapToFixed(19.6), 1};
  EXPECT_EQ(CoverageCounts({{a, b, c}}), CoverageCounts({{a, c, b}}));
}

struct TilingCase {
  const char* name;
  GridOptions options;
};

void PrintTo(const TilingCase& tilingCase, std::ostream* out) {
  *out << tilingCase.name;
}

class WatertightTiling : public testing::TestWithParam<TilingCase> {};

TEST_P(WatertightTiling, EveryCellIsCoveredExactlyOnce) {
  ExpectEveryCellOnce(CoverageCounts(TilingMesh(GetParam().options)));
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, WatertightTiling,
    testing::Values(
        TilingCase{"VerticesOnCellCenters", {}},
        TilingCase{"UnitStepOnCenters", {.stepCells = 1.0}},
        TilingCase{"Jittered", {.stepCells = 2.7, .jitterCells = 0.9, .seed = 7}},
        TilingCase{"Rotated", {.stepCells = 2.5, .rotationRadians = 0.3}},
        TilingCase{"RotatedJittered",
                   {.stepCells = 1.7, .jitterCells = 0.6, .rotationRadians = 1.1, .seed = 3}},
        TilingCase{"FlippedDiagonals", {.stepCells = 2.0, .flipDiagonals = true}},
        TilingCase{"VertexOrderRotated", {.jitterCells = 0.7, .rotateVertexOrder = 1}},
        TilingCase{"VertexOrderRotatedTwice",
                   {.stepCells = 1.3, .jitterCells = 0.4, .rotateVertexOrder = 2, .seed = 11}},
        TilingCase{"Slivers", {.stepCells = 0.37, .jitterCells = 0.15, .seed = 5}}),
    [](const testing::TestParamInfo<TilingCase>& info) { return std::string(info.param.name); });

TEST(Rasterizer, PerspectiveDepthDoesNotChangeCoverage) {
  // The same projected quads, each vertex with its own w = 1/z for z in [0.1, 4].
  const std::vector<Triangle> flat = TilingMesh({.stepCells = 2.1, .jitterCells = 0.7, .seed = 4});
  std::vector<Triangle> deep = flat;
  std::mt19937 random(17);
  std::uniform_real_distribution<float> depth(0.1F, 4.0F);
  for (Triangle& t : deep) {
    for (RasterVertex& v : t) v.w = 1.0F / depth(random);
  }
  EXPECT_EQ(TriangleMap(flat).FaceNumbers(), TriangleMap(deep).FaceNumbers());
  ExpectEveryCellOnce(CoverageCounts(deep));
}

TEST(Rasterizer, CoverageMovesWithWholeCellTranslation) {
  GridOptions options{.stepCells = 2.3, .jitterCells = 0.8, .seed = 9};
  // Per-triangle coverage, so the comparison sees which triangle owns each sample.
  const std::vector<Triangle> base = TilingMesh(options);
  options.shiftCells = 3.0;
  const std::vector<Triangle> shifted = TilingMesh(options);
  ASSERT_EQ(base.size(), shifted.size());
  const CellBuffer a = TriangleMap(base), b = TriangleMap(shifted);
  for (int row = 0; row + 3 < kHeight; ++row) {
    for (int col = 0; col + 3 < kWidth; ++col) {
      EXPECT_EQ(a.FaceNumber(col, row), b.FaceNumber(col + 3, row + 3)) << col << "," << row;
    }
  }
}

TEST(Rasterizer, HugeCoordinatesNeitherOverflowNorLeak) {
  // A sliver from far outside the view crosses it; coordinates at +-1e6 cells.
  const RasterVertex far1{SnapToFixed(-1e6), SnapToFixed(-1e6), 1},
      far2{SnapToFixed(1e6), SnapToFixed(1e6 + 0.9), 1},
      far3{SnapToFixed(1e6), SnapToFixed(-1e6), 1}, far4{SnapToFixed(-1e6), SnapToFixed(1e6), 1};
  // Two triangles sharing the long diagonal: together they tile the view.
  ExpectEveryCellOnce(CoverageCounts({{far1, far2, far3}, {far1, far4, far2}}));
}

}  // namespace
}  // namespace termshade
