// Outward orientation (SPEC 10): closed parts with negative signed volume are
// turned outward once when the scene is prepared; open sheets keep their winding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "geometry/OutwardOrientation.h"
#include "io/scenes/SceneGenerators.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

// The edge uses of a mesh big enough for the load threads (a quad and a
// hidden edge among its triangles, some faces reversed) are every face
// edge once, grouped by undirected edge in (smaller, larger vertex, face)
// order: what a single sorted list of them gives.
TEST(EdgeAdjacency, SplitOverThreadsEqualsOneSortedList) {
  Mesh mesh = GenerateTriangleSphere(300'000);
  for (size_t f = 0; f < mesh.FaceCount(); f += 7) ReverseFace(mesh, f);
  mesh.edgeHidden[4] = 1;
  const uint32_t quad[4] = {0, 1, 2, 3};
  mesh.AddFace(quad);
  using Use = std::array<uint32_t, 5>;  // smaller, larger vertex, face, forward, hidden
  std::vector<Use> expected;
  for (uint32_t f = 0; f < mesh.FaceCount(); ++f) {
    const auto corners = mesh.Face(f);
    for (size_t i = 0; i < corners.size(); ++i) {
      const uint32_t a = corners[i], b = corners[(i + 1) % corners.size()];
      if (a == b) continue;
      expected.push_back(
          {std::min(a, b), std::max(a, b), f, a < b ? 1U : 0U, mesh.EdgeHidden(f, i) ? 1U : 0U});
    }
  }
  std::sort(expected.begin(), expected.end());
  const EdgeAdjacency adjacency(mesh.verticesFile.size(), mesh);
  std::vector<Use> actual;
  adjacency.ForEachEdge([&](uint32_t low, std::span<const EdgeUse> uses) {
    for (const EdgeUse& use : uses) {
      actual.push_back(
          {low, use.highVertex, use.Face(), use.Forward() ? 1U : 0U, use.Hidden() ? 1U : 0U});
    }
  });
  EXPECT_EQ(adjacency.UseCount(), expected.size());
  EXPECT_TRUE(actual == expected);
}

Mesh Cube(Vec3 offset = {}) {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.verticesFile.push_back(Vec3{double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)} +
                                offset);
  }
  // Counter-clockwise seen from outside.
  const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& face : faces) mesh.AddFace(face);
  return mesh;
}

// The same faces run backwards: an inside-out cube.
Mesh Reversed(Mesh mesh, size_t firstFace = 0, size_t endFace = SIZE_MAX) {
  for (size_t f = firstFace; f < std::min(endFace, mesh.FaceCount()); ++f) ReverseFace(mesh, f);
  return mesh;
}

std::vector<uint32_t> Corners(const Mesh& mesh) {
  return mesh.faceCorners;
}

TEST(OutwardOrientation, ReversedCubeDrawsAsTheOutwardCube) {
  const Scene outward = PrepareScene(Cube());
  const Scene inward = PrepareScene(Reversed(Cube()));
  EXPECT_EQ(outward.facesTurnedOutward, 0U);
  EXPECT_EQ(inward.facesTurnedOutward, 6U);
  EXPECT_EQ(Corners(inward.SourceMesh()), Corners(outward.SourceMesh()));
  EXPECT_TRUE(inward.convexClosedSolid);
  for (Method method : {Method::kZBuffer, Method::kPainter, Method::kCull, Method::kAuto}) {
    RenderOptions options;
    options.method = method;
    for (const auto& [theta, phi] : {std::pair{0.3, 1.3}, std::pair{2.1, 0.6}}) {
      const std::string expected = test::RenderFrame(outward, theta, phi, 60, 20, options).Text();
      EXPECT_EQ(test::RenderFrame(inward, theta, phi, 60, 20, options).Text(), expected)
          << MethodName(method);
      EXPECT_NE(expected.find('@'), std::string::npos);
    }
  }
}

TEST(OutwardOrientation, OpenSheetKeepsItsWinding) {
  Mesh open = Reversed(Cube());
  open.faceCorners.resize(open.faceStarts[5]);  // the last face removed: a box without a lid
  open.edgeHidden.resize(open.faceStarts[5]);
  open.faceStarts.pop_back();
  const std::vector<uint32_t> before = Corners(open);
  const Scene scene = PrepareScene(open);
  EXPECT_EQ(scene.facesTurnedOutward, 0U);
  EXPECT_EQ(Corners(scene.SourceMesh()), before);
}

TEST(OutwardOrientation, InconsistentWindingIsLeftAlone) {
  const Mesh mixed = Reversed(Reversed(Cube()), 0, 1);  // one face runs the other way
  const Scene scene = PrepareScene(mixed);
  EXPECT_EQ(scene.facesTurnedOutward, 0U);
  EXPECT_EQ(Corners(scene.SourceMesh()), Corners(mixed));
}

TEST(OutwardOrientation, OnlyTheInsideOutPartTurns) {
  Mesh two = Cube();
  const Mesh second = Reversed(Cube({3, 0, 0}));
  const auto offset = static_cast<uint32_t>(two.verticesFile.size());
  two.verticesFile.insert(two.verticesFile.end(), second.verticesFile.begin(),
                          second.verticesFile.end());
  for (size_t f = 0; f < second.FaceCount(); ++f) {
    std::vector<uint32_t> corners;
    for (uint32_t v : second.Face(f)) corners.push_back(v + offset);
    two.AddFace(corners);
  }
  const Scene scene = PrepareScene(two);
  EXPECT_EQ(scene.facesTurnedOutward, 6U);
  for (size_t f = 0; f < 12; ++f) {
    const Vec3 cubeCenter = scene.verticesWorld[f < 6 ? 0 : 8] + Vec3{0.5, 0.5, 0.5};
    const Vec3 corner = scene.verticesWorld[scene.Face(f)[0]];
    EXPECT_GT(Dot(scene.facePlanesWorld[f].normal, corner - cubeCenter), 0.0) << f;
  }
}

TEST(OutwardOrientation, HiddenEdgesStayWithTheirEdges) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const uint32_t corners[] = {0, 1, 2, 3};
  const uint8_t hidden[] = {0, 1, 0, 0};  // the edge 1-2
  mesh.AddFace(corners, hidden);
  ReverseFace(mesh, 0);
  EXPECT_EQ(mesh.faceCorners, (std::vector<uint32_t>{0, 3, 2, 1}));
  EXPECT_EQ(mesh.edgeHidden, (std::vector<uint8_t>{0, 0, 1, 0}));  // now the edge 2-1
}

TEST(OutwardOrientation, InsideOutRealModelTurnsOnceAndDrawsWithCulling) {
  const Scene scene =
      PrepareScene(test::LoadMesh("tests/models/real/wuson_inside_out.off"), UpAxis::kPlusZ);
  EXPECT_GT(scene.facesTurnedOutward, scene.FaceCount() / 2);
  EXPECT_EQ(PrepareScene(scene.SourceMesh()).facesTurnedOutward, 0U);  // done once, for good
  // Outward, culling back faces hides almost nothing the Z-buffer shows with
  // both sides drawn (the file has a few open parts, seen through their gaps).
  RenderOptions culled, twoSided;
  twoSided.cullBackFaces = false;
  // The file as it was (every plane flipped back) shows its inside instead.
  Scene asFiled = scene;
  for (FacePlane& plane : asFiled.facePlanesWorld) plane = {-plane.normal, -plane.offset};
  const test::Frame front = test::RenderFrame(scene, 0.3, 1.3, 80, 24, culled);
  const test::Frame both = test::RenderFrame(scene, 0.3, 1.3, 80, 24, twoSided);
  const test::Frame inside = test::RenderFrame(asFiled, 0.3, 1.3, 80, 24, culled);
  int drawn = 0, differing = 0, differingAsFiled = 0;
  for (int row = 0; row < 24; ++row) {
    for (int col = 0; col < 80; ++col) {
      drawn += both.cells.Level(col, row) >= 0 ? 1 : 0;
      differing += front.cells.Level(col, row) != both.cells.Level(col, row) ? 1 : 0;
      differingAsFiled += inside.cells.Level(col, row) != both.cells.Level(col, row) ? 1 : 0;
    }
  }
  EXPECT_GT(drawn, 150);
  EXPECT_LE(differing * 20, drawn) << front.Text() << both.Text();
  EXPECT_GE(differingAsFiled * 3, drawn) << inside.Text();
}

TEST(OutwardOrientation, ShippedScenesAreAlreadyOutward) {
  for (const std::string& name : GeneratedSceneNames()) {
    EXPECT_EQ(test::LoadScene("data/" + name + ".dat").facesTurnedOutward, 0U) << name;
  }
}

}  // namespace
}  // namespace termshade
