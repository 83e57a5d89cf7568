#include "geometry/WeldVertices.h"

#include <gtest/gtest.h>

#include <array>

#include "io/scenes/SceneGenerators.h"

namespace termshade {
namespace {

// Each face with corners of its own, as some importers give them.
Mesh Unwelded(const Mesh& source) {
  Mesh mesh;
  for (size_t f = 0; f < source.FaceCount(); ++f) {
    std::vector<uint32_t> corners;
    for (const uint32_t v : source.Face(f)) {
      corners.push_back(static_cast<uint32_t>(mesh.verticesFile.size()));
      mesh.verticesFile.push_back(source.verticesFile[v]);
    }
    mesh.AddFace(corners);
  }
  return mesh;
}

TEST(WeldVertices, GivesBackTheSharedMesh) {
  const Mesh cube = *GenerateScene("cube");
  Mesh mesh = Unwelded(cube);
  ASSERT_GT(mesh.verticesFile.size(), cube.verticesFile.size());
  WeldExactPositions(mesh);
  EXPECT_EQ(mesh.verticesFile.size(), cube.verticesFile.size());
  ASSERT_EQ(mesh.FaceCount(), cube.FaceCount());
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    ASSERT_EQ(mesh.Face(f).size(), cube.Face(f).size());
    for (size_t i = 0; i < mesh.Face(f).size(); ++i) {
      EXPECT_EQ(mesh.verticesFile[mesh.Face(f)[i]], cube.verticesFile[cube.Face(f)[i]]);
    }
  }
}

TEST(WeldVertices, LeavesAWeldedMeshAsItIs) {
  const Mesh sphere = GenerateSphere(12, 16);
  Mesh mesh = sphere;
  WeldExactPositions(mesh);
  EXPECT_EQ(mesh.faceCorners, sphere.faceCorners);
  EXPECT_EQ(mesh.verticesFile.size(), sphere.verticesFile.size());
}

TEST(WeldVertices, KeepsNearbyButDifferentPositionsApart) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 1e-12}, {0, 1, 0}};
  mesh.AddFace(std::array<uint32_t, 3>{0, 1, 2});
  mesh.AddFace(std::array<uint32_t, 3>{3, 4, 5});
  mesh.segments.push_back({3, 5});
  WeldExactPositions(mesh);
  EXPECT_EQ(mesh.verticesFile.size(), 4U);
  EXPECT_EQ(mesh.faceCorners, (std::vector<uint32_t>{0, 1, 2, 0, 3, 2}));
  EXPECT_EQ(mesh.segments.front(), (std::array<uint32_t, 2>{0, 2}));
}

}  // namespace
}  // namespace termshade
