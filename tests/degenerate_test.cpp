// Degenerate and hostile models render without crashing, NaN or UB in every
// method (the sanitizer build runs these under ASan and UBSan).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/load/ModelLoader.h"
#include "io/read/DatReader.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

Scene FromText(const std::string& text) {
  Loaded<Mesh> mesh = ParseDat(text, "inline.dat");
  EXPECT_TRUE(mesh.Ok()) << (mesh.Ok() ? "" : mesh.Error().ToString());
  return PrepareScene(mesh.Ok() ? std::move(mesh.Value()) : Mesh{});
}

void RenderEveryWay(const Scene& scene) {
  for (Method method : {Method::kZBuffer, Method::kPainter, Method::kCull, Method::kWire}) {
    for (bool cull : {true, false}) {
      RenderOptions options;
      options.method = method;
      options.cullBackFaces = cull;
      for (double rhoScale : {1.0, 0.01, 1e-9}) {
        const double rho = DefaultView(scene.diagonalModelUnits).rho * rhoScale;
        const test::Frame frame = test::RenderFrame(scene, 0.4, 1.1, 40, 12, options, rho);
        for (size_t i = 0; i < frame.cells.Glyphs().size(); ++i) {
          const double depth = frame.depth.DepthAt(i);
          EXPECT_TRUE(std::isfinite(depth) && depth >= 0.0) << "cell " << i;
        }
      }
    }
  }
}

// Read as a .dat, past the loader (which refuses a model with no face to draw):
// the pipeline must still take it, as scenes built in code reach it unchecked.
TEST(Degenerate, ZeroLengthEdgeFoundByTheFuzzer) {
  RenderEveryWay(
      FromText(test::ReadFile(test::SourcePath("tests/models/good/zero_length_edge.dat"))));
  const Loaded<Mesh> loaded =
      LoadModelFile(test::SourcePath("tests/models/good/zero_length_edge.dat"));
  ASSERT_FALSE(loaded.Ok());
  EXPECT_NE(loaded.Error().message.find("its one face has no area"), std::string::npos);
}

TEST(Degenerate, CollinearAndDuplicateCornersDrawNothing) {
  const Scene scene =
      FromText("1 0 0 0\n2 1 1 1\n3 2 2 2\n4 0 0 0\nFaces:\n1 2 3.\n1 1 1.\n1 4 2.\n");
  RenderEveryWay(scene);
  RenderOptions options;
  const test::Frame frame = test::RenderFrame(scene, 0.4, 1.1, 40, 12, options);
  for (uint32_t face : frame.cells.FaceNumbers()) EXPECT_EQ(face, 0U);
}

TEST(Degenerate, EmptyAndSinglePointModels) {
  RenderEveryWay(FromText("Faces:\n"));
  RenderEveryWay(FromText("1 5 5 5\nFaces:\n"));
  RenderEveryWay(FromText("1 5 5 5\n2 5 5 5\n3 5 5 5\nFaces:\n1 2 3.\n"));
}

TEST(Degenerate, HugeAndTinyCoordinates) {
  RenderEveryWay(FromText("1 -1e300 0 0\n2 1e300 0 0\n3 0 1e300 0\nFaces:\n1 2 3.\n3 2 1.\n"));
  RenderEveryWay(FromText("1 0 0 0\n2 1e-300 0 0\n3 0 1e-300 0\nFaces:\n1 2 3.\n3 2 1.\n"));
  RenderEveryWay(
      FromText("1 1e5 1e5 1e5\n2 100001 1e5 1e5\n3 1e5 100001 1e5\nFaces:\n1 2 3.\n3 2 1.\n"));
}

TEST(Degenerate, SelfIntersectingAndNonPlanarFaces) {
  RenderEveryWay(FromText("1 0 0 0\n2 2 2 0\n3 2 0 0\n4 0 2 0\nFaces:\n1 2 3 4.\n4 3 2 1.\n"));
  RenderEveryWay(FromText("1 0 0 0\n2 1 0 1\n3 1 1 0\n4 0 1 1\nFaces:\n1 2 3 4.\n4 3 2 1.\n"));
}

}  // namespace
}  // namespace termshade

namespace termshade {
namespace {

// Issue 32: one triangle repeated (the first kept, the faces keep their
// numbers), one polygon repeated (triangulated once), drawn every way.
TEST(Degenerate, RepeatedTrianglesAreDrawnOnce) {
  std::string text = "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 1\nFaces:\n";
  for (int i = 0; i < 100; ++i) text += "1 2 3.\n";
  text += "2 4 3.\n";
  const Scene scene = FromText(text);
  EXPECT_EQ(scene.FaceCount(), 101U);
  ASSERT_EQ(scene.triangles.size(), 2U);
  EXPECT_EQ(scene.TriangleFace(0), 0U);
  EXPECT_EQ(scene.TriangleFace(1), 100U);
  EXPECT_EQ(scene.FaceTrianglesBegin(1), 1U);  // faces 1..99: no triangles of their own
  EXPECT_EQ(scene.FaceTrianglesBegin(100), 1U);
  EXPECT_EQ(scene.FaceTrianglesBegin(101), 2U);
  EXPECT_EQ(scene.Face(100).size(), 3U);  // the faces are kept: the triangles no longer give them
  RenderEveryWay(scene);
}

TEST(Degenerate, RepeatedTrianglesWithTheirOwnVerticesAreDrawnOnce) {
  // Unwelded: every copy has three vertices of its own at the same places;
  // the reverse turn (the other side) is another triangle.
  std::string text, faces = "Faces:\n";
  for (int i = 0; i < 100; ++i) {
    const int v = 3 * i + 1;
    text += std::to_string(v) + " 0 0 0\n" + std::to_string(v + 1) + " 1 0 0\n" +
            std::to_string(v + 2) + " 0 1 0\n";
    faces +=
        i == 50
            ? std::to_string(v) + " " + std::to_string(v + 2) + " " + std::to_string(v + 1) + ".\n"
            : std::to_string(v + 1) + " " + std::to_string(v + 2) + " " + std::to_string(v) + ".\n";
  }
  const Scene scene = FromText(text + faces);
  EXPECT_EQ(scene.FaceCount(), 100U);
  ASSERT_EQ(scene.triangles.size(), 2U);
  EXPECT_EQ(scene.TriangleFace(0), 0U);
  EXPECT_EQ(scene.TriangleFace(1), 50U);
  RenderEveryWay(scene);
}

TEST(Degenerate, ARepeatedPolygonIsTriangulatedOnce) {
  std::string text, face;
  for (int i = 0; i < 100; ++i) {
    const double angle = 2 * 3.141592653589793 * i / 100;
    text += std::to_string(i + 1) + " " + std::to_string(std::cos(angle)) + " " +
            std::to_string(std::sin(angle)) + " 0\n";
    face += std::to_string(i + 1) + " ";
  }
  text += "Faces:\n";
  for (int i = 0; i < 2000; ++i) text += face + ".\n";
  const Scene scene = FromText(text);
  EXPECT_EQ(scene.FaceCount(), 2000U);
  EXPECT_EQ(scene.triangles.size(), 98U);
  RenderEveryWay(scene);
}

}  // namespace
}  // namespace termshade
