// A prepared scene keeps no second copy of its model, yet gives it back bit
// for bit: faces from the triangles, file vertices from world space.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "geometry/FaceNormal.h"
#include "geometry/Scene.h"
#include "geometry/Triangulate.h"
#include "io/scenes/SceneGenerators.h"

namespace termshade {
namespace {

void ExpectSameMesh(const Mesh& actual, const Mesh& expected) {
  ASSERT_EQ(actual.verticesFile.size(), expected.verticesFile.size());
  EXPECT_EQ(std::memcmp(actual.verticesFile.data(), expected.verticesFile.data(),
                        expected.verticesFile.size() * sizeof(Vec3)),
            0);
  EXPECT_EQ(actual.faceCorners, expected.faceCorners);
  EXPECT_EQ(actual.faceStarts, expected.faceStarts);
  EXPECT_EQ(actual.edgeHidden, expected.edgeHidden);
}

TEST(SceneSource, TriangleSphereKeepsNoFacesAndNoVertices) {
  const Mesh mesh = GenerateTriangleSphere(2000);
  const Scene scene = PrepareScene(mesh, UpAxis::kPlusY);
  EXPECT_TRUE(scene.source.faces.corners.empty());
  EXPECT_TRUE(scene.source.verticesFile.empty());
  ExpectSameMesh(scene.SourceMesh(), mesh);
}

TEST(SceneSource, OffsetDoublesAndPolygonsComeBackExactly) {
  Mesh mesh = GenerateScene("sphere_cone").value();
  for (Vec3& p : mesh.verticesFile) p = p * 0.1 + Vec3{1e3 / 3.0, -7.0 / 3.0, 1e-7};
  mesh.verticesFile[0].x = -0.0;  // a signed zero is kept as it is
  const Scene scene = PrepareScene(mesh, UpAxis::kMinusX);
  // Some do not round-trip through world space, so they are kept.
  EXPECT_FALSE(scene.source.inexactVertices.empty() && scene.source.verticesFile.empty());
  ExpectSameMesh(scene.SourceMesh(), mesh);
  for (size_t v = 0; v < mesh.verticesFile.size(); ++v) {
    const Vec3 p = scene.VertexFile(v);
    EXPECT_EQ(std::memcmp(&p, &mesh.verticesFile[v], sizeof(Vec3)), 0) << v;
  }
}

// World space computed in place on the load threads equals one plain loop
// of ZUpFromFile(file) - center, for every up axis, both when a few file
// vertices are listed and when all are kept; the file comes back bit for bit.
TEST(SceneSource, WorldVerticesOnLoadThreadsEqualOneLoop) {
  const Mesh sphere = GenerateTriangleSphere(600'000);  // ~300k vertices: two threads
  for (const bool shifted : {false, true}) {
    Mesh mesh = sphere;
    if (shifted) {  // a center off every grid the coordinates are on
      for (Vec3& p : mesh.verticesFile) p = p * 0.1 + Vec3{0.1 / 3.0, 0.1 / 7.0, 0.1 / 11.0};
    } else {
      // Bounds centered on 0, where only -0.0 (0.0 after - 0 + 0) is inexact.
      mesh.verticesFile.push_back({2.0, 2.0, 2.0});
      mesh.verticesFile.push_back({-2.0, -2.0, -2.0});
    }
    mesh.verticesFile[7] = {NAN, 1.0, 2.0};  // not finite: outside the bounds and radius
    mesh.verticesFile[9] = {-0.0, -0.0, -0.0};
    for (const UpAxis up : {UpAxis::kPlusX, UpAxis::kMinusX, UpAxis::kPlusY, UpAxis::kMinusY,
                            UpAxis::kPlusZ, UpAxis::kMinusZ}) {
      Vec3 low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
      for (const Vec3& pFile : mesh.verticesFile) {
        const Vec3 p = ZUpFromFile(up, pFile);
        if (!IsFinite(p)) continue;
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
      }
      const Vec3 center = (low + high) * 0.5;
      const Scene scene = PrepareScene(mesh, up);
      ASSERT_EQ(scene.verticesWorld.size(), mesh.verticesFile.size());
      double radius = 0.0;
      for (size_t v = 0; v < mesh.verticesFile.size(); ++v) {
        const Vec3 expected = ZUpFromFile(up, mesh.verticesFile[v]) - center;
        ASSERT_EQ(std::memcmp(&scene.verticesWorld[v], &expected, sizeof(Vec3)), 0) << v;
        if (IsFinite(ZUpFromFile(up, mesh.verticesFile[v])))
          radius = std::max(radius, Length(expected));
        const Vec3 file = scene.VertexFile(v);
        ASSERT_EQ(std::memcmp(&file, &mesh.verticesFile[v], sizeof(Vec3)), 0) << v;
      }
      EXPECT_EQ(scene.radiusModelUnits, radius);
      EXPECT_EQ(scene.diagonalModelUnits, Length(high - low));
      // Unshifted, few are inexact (listed); shifted, past an eighth (all kept).
      EXPECT_EQ(scene.source.verticesFile.empty(), !shifted) << static_cast<int>(up);
      EXPECT_EQ(scene.source.inexactVertices.empty(), shifted) << static_cast<int>(up);
    }
  }
}

// Every triangle's face, read through the maps, holds it: the face's range
// of triangles covers triangle t, and the ranges tile the triangles in order.
void ExpectFaceMapsAgree(const Scene& scene) {
  ASSERT_EQ(scene.FaceTrianglesBegin(0), 0U);
  ASSERT_EQ(scene.FaceTrianglesBegin(scene.FaceCount()), scene.triangles.size());
  for (size_t f = 0; f < scene.FaceCount(); ++f) {
    ASSERT_LE(scene.FaceTrianglesBegin(f), scene.FaceTrianglesBegin(f + 1));
    for (uint32_t t = scene.FaceTrianglesBegin(f); t < scene.FaceTrianglesBegin(f + 1); ++t) {
      ASSERT_EQ(scene.TriangleFace(t), f);
    }
  }
}

TEST(SceneFaceMaps, ImplicitWhenEveryFaceIsOneTriangle) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(2000), UpAxis::kPlusY);
  EXPECT_TRUE(scene.faceTriangleStarts.empty());
  EXPECT_TRUE(scene.triangleFaces.empty());
  EXPECT_EQ(scene.triangles.size(), scene.FaceCount());
  ExpectFaceMapsAgree(scene);
}

TEST(SceneFaceMaps, ExplicitForPolygonsAndFacesWithoutTriangles) {
  // Polygons from the start.
  const Scene polygons = PrepareScene(GenerateScene("sphere_cone").value());
  EXPECT_EQ(polygons.faceTriangleStarts.size(), polygons.FaceCount() + 1);
  EXPECT_EQ(polygons.triangleFaces.size(), polygons.triangles.size());
  ExpectFaceMapsAgree(polygons);
  // Triangles first, then a quad; then a triangle with a non-finite corner (no triangles).
  Mesh mesh = GenerateTriangleSphere(200);
  const auto v = static_cast<uint32_t>(mesh.verticesFile.size());
  mesh.verticesFile.insert(mesh.verticesFile.end(),
                           {{5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0}, {NAN, 0, 0}});
  const std::vector<uint32_t> quad{v, v + 1, v + 2, v + 3}, broken{v, v + 1, v + 4};
  mesh.AddFace(quad);
  mesh.AddFace(broken);
  const Scene mixed = PrepareScene(mesh);
  EXPECT_EQ(mixed.triangles.size(), mixed.FaceCount());  // 2 for the quad, 0 for the last
  EXPECT_EQ(mixed.FaceTrianglesBegin(mixed.FaceCount() - 1), mixed.triangles.size());
  EXPECT_EQ(mixed.faceTriangleStarts.size(), mixed.FaceCount() + 1);
  ExpectFaceMapsAgree(mixed);
}

// Faces that are all triangles are triangulated on the load threads: each
// face's triangle is TriangulatePolygon's, and a face it would not give one
// (two corners at one point, last of all) sends the whole mesh down the
// general path with the same result.
TEST(SceneTriangles, ThreadedTrianglesEqualTriangulatePolygon) {
  Mesh sphere = GenerateTriangleSphere(300000);
  for (const bool degenerateLast : {false, true}) {
    Mesh mesh = sphere;
    if (degenerateLast) {
      const auto v = static_cast<uint32_t>(mesh.verticesFile.size());
      mesh.verticesFile.insert(mesh.verticesFile.end(), {{5, 0, 0}, {5, 0, 0}, {6, 1, 0}});
      mesh.AddFace(std::vector<uint32_t>{v, v + 1, v + 2});
    }
    const Scene scene = PrepareScene(mesh, UpAxis::kPlusY);
    std::vector<SceneTriangle> expected;
    std::vector<CornerTriangle> triangles;
    for (size_t f = 0; f < scene.FaceCount(); ++f) {
      const auto corners = scene.Face(f);
      std::vector<Vec3> points;
      for (const uint32_t c : corners) points.push_back(scene.verticesWorld[c]);
      triangles.clear();
      TriangulatePolygon(points, triangles);
      for (const CornerTriangle& t : triangles) {
        expected.push_back({{corners[t[0]], corners[t[1]], corners[t[2]]}});
      }
    }
    ASSERT_EQ(scene.triangles.size(), expected.size()) << degenerateLast;
    for (size_t t = 0; t < expected.size(); ++t) {
      ASSERT_EQ(scene.triangles[t].vertices, expected[t].vertices) << t;
    }
    EXPECT_EQ(scene.faceTriangleStarts.empty(), !degenerateLast);
    ExpectFaceMapsAgree(scene);
  }
}

// The planes, computed over the load threads in ranges of faces, are each
// face's plane as one loop gives it: no face skipped or given a neighbour's.
// (Every face here is its one triangle: the planes take the fixed-size path.)
TEST(ScenePlanes, SplitOverThreadsEqualOneLoop) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(300000), UpAxis::kPlusY);
  ASSERT_EQ(scene.facePlanesWorld.size(), scene.FaceCount());
  for (size_t f = 0; f < scene.FaceCount(); ++f) {
    const auto corners = scene.Face(f);
    const auto pointAt = [&](size_t i) { return scene.verticesWorld[corners[i]]; };
    Vec3 mean;
    for (size_t i = 0; i < corners.size(); ++i) mean = mean + pointAt(i);
    mean = mean * (1.0 / static_cast<double>(corners.size()));
    const Vec3 normal = Normalized(NewellNormal(corners.size(), pointAt));
    const FacePlane expected{normal, Dot(normal, mean)};
    ASSERT_EQ(std::memcmp(&scene.facePlanesWorld[f], &expected, sizeof expected), 0) << f;
  }
}

}  // namespace
}  // namespace termshade
