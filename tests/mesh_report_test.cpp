// ReportMesh: parts, open and non-manifold edges, colours and bounds, counted
// exactly on small meshes whose answers are known.
#include <gtest/gtest.h>

#include "geometry/MeshReport.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

Mesh Quads(std::initializer_list<std::array<uint32_t, 4>> faces, size_t vertexCount) {
  Mesh mesh;
  for (size_t v = 0; v < vertexCount; ++v)
    mesh.verticesFile.push_back({static_cast<double>(v), static_cast<double>(v % 3), -1.0});
  for (const auto& face : faces) mesh.AddFace(face);
  return mesh;
}

TEST(MeshReport, TheCubeIsOneClosedPart) {
  const MeshReport report = ReportMesh(test::LoadMesh("data/cube.dat"));
  EXPECT_EQ(report.vertices, 8U);
  EXPECT_EQ(report.faces, 6U);
  EXPECT_EQ(report.parts, 1U);
  EXPECT_EQ(report.openEdges, 0U);
  EXPECT_EQ(report.nonManifoldEdges, 0U);
  EXPECT_EQ(report.faceColours, 0U);
}

TEST(MeshReport, CountsPartsAndOpenEdges) {
  // Two quads sharing an edge, and a third quad apart: 2 parts, 6 + 4 open edges.
  const Mesh mesh = Quads({{0, 1, 2, 3}, {1, 4, 5, 2}, {6, 7, 8, 9}}, 10);
  const MeshReport report = ReportMesh(mesh);
  EXPECT_EQ(report.parts, 2U);
  EXPECT_EQ(report.openEdges, 10U);
  EXPECT_EQ(report.nonManifoldEdges, 0U);
  EXPECT_DOUBLE_EQ(report.boundsMin.x, 0.0);
  EXPECT_DOUBLE_EQ(report.boundsMax.x, 9.0);
  EXPECT_DOUBLE_EQ(report.boundsMax.y, 2.0);
  EXPECT_DOUBLE_EQ(report.boundsMin.z, -1.0);
}

TEST(MeshReport, AFinOfThreeFacesIsNonManifold) {
  const Mesh mesh = Quads({{0, 1, 2, 3}, {0, 1, 4, 5}, {0, 1, 6, 7}}, 8);
  const MeshReport report = ReportMesh(mesh);
  EXPECT_EQ(report.nonManifoldEdges, 1U);
  EXPECT_EQ(report.openEdges, 9U);
  EXPECT_EQ(report.parts, 1U);
}

TEST(MeshReport, UnusedVerticesAreNoPartAndOutsideTheBounds) {
  Mesh mesh = Quads({{0, 1, 2, 3}}, 4);
  mesh.verticesFile.push_back({100.0, 100.0, 100.0});  // used by no face
  mesh.faceColors = {Rgb{1, 0, 0}};
  const MeshReport report = ReportMesh(mesh);
  EXPECT_EQ(report.parts, 1U);
  EXPECT_DOUBLE_EQ(report.boundsMax.x, 3.0);
  EXPECT_EQ(report.faceColours, 1U);
}

}  // namespace
}  // namespace termshade
