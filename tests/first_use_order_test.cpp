#include <gtest/gtest.h>

#include <vector>

#include "geometry/FirstUseOrder.h"

namespace termshade {
namespace {

std::vector<Vec3> CornerPositions(const Mesh& mesh) {
  std::vector<Vec3> positions;
  for (const uint32_t corner : mesh.faceCorners) positions.push_back(mesh.verticesFile[corner]);
  for (const auto& segment : mesh.segments) {
    positions.push_back(mesh.verticesFile[segment[0]]);
    positions.push_back(mesh.verticesFile[segment[1]]);
  }
  return positions;
}

TEST(FirstUseOrder, NumbersVerticesAsTheCornersFirstUseThem) {
  Mesh mesh;
  // Vertex 1 is used by no face or segment; the faces use 4, 2, 0 first.
  mesh.verticesFile = {{0, 0, 0}, {9, 9, 9}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {5, 5, 5}};
  mesh.AddFace(std::vector<uint32_t>{4, 2, 0});
  mesh.AddFace(std::vector<uint32_t>{4, 3, 2});
  mesh.segments.push_back({5, 0});
  const std::vector<Vec3> before = CornerPositions(mesh);
  NumberVerticesByFirstUse(mesh);
  EXPECT_EQ(mesh.faceCorners, (std::vector<uint32_t>{0, 1, 2, 0, 3, 1}));
  EXPECT_EQ(mesh.segments[0], (std::array<uint32_t, 2>{4, 2}));
  EXPECT_EQ(mesh.verticesFile.size(), 5U);  // the unused vertex is gone
  EXPECT_EQ(CornerPositions(mesh), before);
  EXPECT_EQ(mesh.FaceCount(), 2U);
}

TEST(FirstUseOrder, LeavesAMeshInFirstUseOrderAsItIs) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.AddFace(std::vector<uint32_t>{0, 1, 2});
  mesh.AddFace(std::vector<uint32_t>{1, 3, 2});
  const Mesh before = mesh;
  NumberVerticesByFirstUse(mesh);
  EXPECT_EQ(mesh.faceCorners, before.faceCorners);
  EXPECT_EQ(mesh.verticesFile, before.verticesFile);
}

}  // namespace
}  // namespace termshade
