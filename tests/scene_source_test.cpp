// A prepared scene keeps no second copy of its model, yet gives it back bit
// for bit: faces from the triangles, file vertices from world space.
#include <gtest/gtest.h>

#include <cstring>

#include "geometry/Scene.h"
#include "io/SceneGenerators.h"

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

}  // namespace
}  // namespace termshade
