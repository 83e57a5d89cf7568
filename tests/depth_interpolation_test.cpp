// 1/z interpolated linearly in screen space (SPEC 5), through the real rasterizer.
#include <gtest/gtest.h>

#include "geometry/Projection.h"
#include "raster/FixedPoint.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {
namespace {

RasterVertex Project(const Projection& proj, Vec3 pEye) {
  const CellPoint p = ProjectToCell(proj, pEye);
  return {SnapToFixed(p.u), SnapToFixed(p.v), static_cast<float>(p.w)};
}

// SPEC 5's example with the eye looking down -z: A(-1,0,-2), B(1,0,-10), d = 1
// (scaled by 100 to span cells). The segment's midpoint (0,0,-6) projects to
// the screen center X = 0, where linear z would give 8.667 but the true
// depth is 6.
TEST(DepthInterpolation, OneOverZIsExactWhereLinearZIsNot) {
  const Projection proj{100.0, 60.5, 10.5, 2.0};  // cell (60, 10)'s center is X = 0, Y = 0
  const RasterVertex a = Project(proj, {-1, 0, -2});
  const RasterVertex b = Project(proj, {1, 0, -10});
  const RasterVertex c = Project(proj, {0, -0.5, -6});  // below the edge AB on screen
  CellBuffer cells(120, 40);
  DepthBuffer depth;
  depth.Resize(120, 40);
  ASSERT_GT(RasterizeTriangle(a, b, c, 1, DepthRule::kNearestWins, depth, cells), 0);
  ASSERT_EQ(cells.FaceNumber(60, 10), 1U);  // AB is a top edge: its samples belong to it
  const double trueDepth = depth.DepthAt(cells.Index(60, 10));
  EXPECT_NEAR(trueDepth, 6.0, 6.0 * 1e-5);

  // What linear interpolation of z along the projected segment would give.
  const double s = (0.0 - (-50.0)) / (10.0 - (-50.0));
  EXPECT_NEAR(2.0 + s * (10.0 - 2.0), 8.667, 1e-3);
}

TEST(DepthInterpolation, NearerSurfaceWinsWhateverTheOrder) {
  const Projection proj{10.0, 10.0, 5.0, 2.0};
  const RasterVertex nearA = Project(proj, {-5, -3, -5}), nearB = Project(proj, {5, -3, -5}),
                     nearC = Project(proj, {0, 3, -5});
  const RasterVertex farA = Project(proj, {-10, -6, -10}), farB = Project(proj, {10, -6, -10}),
                     farC = Project(proj, {0, 6, -10});
  for (bool nearFirst : {true, false}) {
    CellBuffer cells(20, 10);
    DepthBuffer depth;
    depth.Resize(20, 10);
    if (nearFirst) RasterizeTriangle(nearA, nearB, nearC, 1, DepthRule::kNearestWins, depth, cells);
    RasterizeTriangle(farA, farB, farC, 2, DepthRule::kNearestWins, depth, cells);
    if (!nearFirst)
      RasterizeTriangle(nearA, nearB, nearC, 1, DepthRule::kNearestWins, depth, cells);
    EXPECT_EQ(cells.FaceNumber(10, 5), 1U);
    EXPECT_NEAR(depth.DepthAt(cells.Index(10, 5)), 5.0, 1e-4);
  }
}

TEST(DepthInterpolation, EqualDepthGoesToTheLowerFaceNumberInAnyOrder) {
  const Projection proj{10.0, 10.0, 5.0, 2.0};
  const RasterVertex a = Project(proj, {-5, -3, -5}), b = Project(proj, {5, -3, -5}),
                     c = Project(proj, {0, 3, -5});
  for (bool lowFirst : {true, false}) {
    CellBuffer cells(20, 10);
    DepthBuffer depth;
    depth.Resize(20, 10);
    RasterizeTriangle(a, b, c, lowFirst ? 3 : 7, DepthRule::kNearestWins, depth, cells);
    RasterizeTriangle(a, c, b, lowFirst ? 7 : 3, DepthRule::kNearestWins, depth, cells);
    EXPECT_EQ(cells.FaceNumber(10, 5), 3U);
  }
}

}  // namespace
}  // namespace termshade
