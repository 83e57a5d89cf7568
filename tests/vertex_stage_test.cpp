// The vertex stage (two vertices at a time where the CPU allows) agrees bit
// for bit with the plain projection of SPEC 3, in view and out.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "geometry/ViewingTransform.h"
#include "raster/FixedPoint.h"
#include "raster/VertexStage.h"

namespace termshade {
namespace {

TEST(VertexStage, MatchesThePlainProjectionForEveryVertex) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-6.0, 6.0);
  std::vector<Vec3> vertices;
  for (int i = 0; i < 1001; ++i) {  // odd: the last one has no partner
    vertices.push_back({coordinate(random), coordinate(random), coordinate(random)});
  }
  vertices[10] = {5.0, 0.0, 0.0};        // the eye itself
  vertices[11] = {4.9999999, 0.0, 0.0};  // just in front of it
  const ViewParams view{5.0, 0.0, 1.5707963267948966};
  const Mat4 eyeFromWorld = EyeFromWorld(view);
  const Projection proj{40.0, 40.0, 12.0, 2.0};
  const ViewClipPlanes planes = MakeViewClipPlanes(proj, 1e-6);
  std::vector<RasterVertex> raster(vertices.size());
  std::vector<uint8_t> codes(vertices.size());
  std::vector<double> eyeZ(vertices.size());
  ProjectVertices(vertices, eyeFromWorld, proj, planes, false,
                  {raster.data(), codes.data(), eyeZ.data()});
  int inView = 0;
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec3 pEye = TransformPoint(eyeFromWorld, vertices[i]);
    EXPECT_EQ(eyeZ[i], pEye.z) << i;
    EXPECT_EQ(codes[i], OutCode(planes, pEye)) << i;
    if (codes[i] != 0) continue;
    ++inView;
    const CellPoint p = ProjectToCell(proj, pEye);
    EXPECT_EQ(raster[i].x, SnapToFixed(p.u)) << i;
    EXPECT_EQ(raster[i].y, SnapToFixed(p.v)) << i;
    EXPECT_EQ(raster[i].w, static_cast<float>(p.w)) << i;
  }
  EXPECT_GT(inView, 300);
  EXPECT_LT(inView, 1000);  // some behind the eye or outside the guard band
}

}  // namespace
}  // namespace termshade
