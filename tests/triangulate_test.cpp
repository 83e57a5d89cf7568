// Triangulation by its properties on awkward polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "geometry/FaceNormal.h"
#include "geometry/Triangulate.h"

namespace termshade {
namespace {

double TriangleArea(Vec3 a, Vec3 b, Vec3 c, Vec3 normal) {
  return 0.5 * Dot(Cross(b - a, c - a), normal);
}

// Every property a triangulation of a simple polygon must have.
void ExpectValidTriangulation(const std::vector<Vec3>& polygon) {
  std::vector<CornerTriangle> triangles;
  TriangulatePolygon(polygon, triangles);
  const size_t n = polygon.size();
  ASSERT_EQ(triangles.size(), n - 2);
  const Vec3 normal = Normalized(NewellNormal(polygon));
  const double polygonArea = 0.5 * Length(NewellNormal(polygon));

  // Areas: none negative (no triangle turned over or outside), sum = polygon.
  double sum = 0.0;
  for (const CornerTriangle& t : triangles) {
    const double area = TriangleArea(polygon[t[0]], polygon[t[1]], polygon[t[2]], normal);
    EXPECT_GE(area, -1e-12);
    sum += area;
  }
  EXPECT_NEAR(sum, polygonArea, 1e-9 * (1.0 + polygonArea));

  // Each boundary edge is used exactly once, in the polygon's direction; each
  // inner diagonal twice, once each way.
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const CornerTriangle& t : triangles) {
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  for (uint32_t i = 0; i < n; ++i) {
    const auto j = static_cast<uint32_t>((i + 1) % n);
    EXPECT_EQ((directed[{i, j}]), 1) << "boundary edge " << i << "-" << j;
    EXPECT_EQ((directed[{j, i}]), 0) << "boundary edge used backwards " << j << "-" << i;
  }
  for (const auto& [edge, count] : directed) {
    const bool boundary = (edge.first + 1) % n == edge.second;
    const bool reversedBoundary = (edge.second + 1) % n == edge.first;
    if (!boundary && !reversedBoundary && count > 0) {
      EXPECT_EQ(count, 1);
      const auto reverse = directed.find({edge.second, edge.first});
      EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
          << "diagonal " << edge.first << "-" << edge.second << " used one way only";
    }
  }
}

TEST(Triangulate, ConvexQuad) {
  ExpectValidTriangulation({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
}

TEST(Triangulate, LShapedFace) {
  ExpectValidTriangulation({{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 5, 0}, {0, 5, 0}});
}

TEST(Triangulate, LShapedFaceStartingAtTheReflexCorner) {
  ExpectValidTriangulation({{1, 1, 0}, {1, 5, 0}, {0, 5, 0}, {0, 0, 0}, {3, 0, 0}, {3, 1, 0}});
}

TEST(Triangulate, CollinearLeadingVertices) {
  ExpectValidTriangulation({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}});
}

TEST(Triangulate, StaircaseProfileInAnotherPlane) {
  // The steps' side: non-convex, in the x-z plane, seen from -y.
  std::vector<Vec3> profile{{0, 0, 0}, {0, 0, 3}, {1, 0, 3}, {1, 0, 2},
                            {2, 0, 2}, {2, 0, 1}, {3, 0, 1}, {3, 0, 0}};
  ExpectValidTriangulation(profile);
  std::reverse(profile.begin(), profile.end());
  ExpectValidTriangulation(profile);
}

TEST(Triangulate, CombWithManyReflexCorners) {
  ExpectValidTriangulation({{0, 0, 0},
                            {10, 0, 0},
                            {10, 5, 0},
                            {9, 5, 0},
                            {9, 1, 0},
                            {7, 1, 0},
                            {7, 5, 0},
                            {6, 5, 0},
                            {6, 1, 0},
                            {4, 1, 0},
                            {4, 5, 0},
                            {3, 5, 0},
                            {3, 1, 0},
                            {1, 1, 0},
                            {1, 5, 0},
                            {0, 5, 0}});
}

TEST(Triangulate, SlightlyNonPlanarPolygon) {
  std::vector<Vec3> polygon;
  for (int i = 0; i < 12; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 12;
    polygon.push_back({std::cos(a), std::sin(a), 0.01 * ((i % 2) ? 1 : -1)});
  }
  ExpectValidTriangulation(polygon);
}

TEST(Triangulate, ManySidedCircleWithFarOffset) {
  std::vector<Vec3> polygon;
  for (int i = 0; i < 90; ++i) {
    const double a = -2.0 * std::numbers::pi * i / 90;
    polygon.push_back({1e5 + std::cos(a), 1e5, 1e5 + std::sin(a)});
  }
  ExpectValidTriangulation(polygon);
}

TEST(Triangulate, DuplicateConsecutiveCornersAreDropped) {
  const std::vector<Vec3> polygon{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
  std::vector<CornerTriangle> triangles;
  TriangulatePolygon(polygon, triangles);
  EXPECT_EQ(triangles.size(), 2U);
  for (const CornerTriangle& t : triangles) {
    EXPECT_GT(TriangleArea(polygon[t[0]], polygon[t[1]], polygon[t[2]], {0, 0, 1}), 0.0);
  }
}

TEST(Triangulate, DegenerateInputNeverLoopsOrCrashes) {
  std::vector<CornerTriangle> triangles;
  TriangulatePolygon(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, triangles);
  EXPECT_EQ(triangles.size(), 2U);  // all collinear: empty triangles, no crash
  triangles.clear();
  TriangulatePolygon(std::vector<Vec3>{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, triangles);
  EXPECT_TRUE(triangles.empty());
  triangles.clear();
  TriangulatePolygon(std::vector<Vec3>{{0, 0, 0}, {NAN, 0, 0}, {1, 1, 0}}, triangles);
  EXPECT_TRUE(triangles.empty());
  triangles.clear();
  // A bow tie (self-intersecting): still n - 2 triangles, still terminates.
  TriangulatePolygon(std::vector<Vec3>{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}}, triangles);
  EXPECT_EQ(triangles.size(), 2U);
}

TEST(Triangulate, LargeCombStaysCorrectAndHostileOnesStayBounded) {
  // A comb: every other corner reflex. 400 corners are triangulated properly.
  auto comb = [](int teeth) {
    std::vector<Vec3> polygon{{0, 0, 0}, {2.0 * teeth, 0, 0}};
    for (int t = teeth - 1; t >= 0; --t) {
      polygon.push_back({2.0 * t + 2, 5, 0});
      polygon.push_back({2.0 * t + 1, 5, 0});
      polygon.push_back({2.0 * t + 1, 1, 0});
      polygon.push_back({2.0 * t, 1, 0});
    }
    polygon.back() = {0, 5, 0};
    return polygon;
  };
  ExpectValidTriangulation(comb(100));
  // 40,000 corners: the budget ends the search; still n - 2 triangles, quickly.
  const std::vector<Vec3> hostile = comb(10000);
  std::vector<CornerTriangle> triangles;
  TriangulatePolygon(hostile, triangles);
  EXPECT_EQ(triangles.size(), hostile.size() - 2);
}

TEST(FaceNormal, NewellIsRightWithCollinearLeadingCorners) {
  const Vec3 n = Normalized(
      NewellNormal(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}));
  EXPECT_NEAR(n.z, 1.0, 1e-15);
  const Vec3 m =
      Normalized(NewellNormal(std::vector<Vec3>{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}));
  EXPECT_NEAR(m.z, -1.0, 1e-15);
}

}  // namespace
}  // namespace termshade
