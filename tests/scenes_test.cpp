// The shipped scenes are what their comments in data/README.md say.
#include <gtest/gtest.h>

#include <map>

#include "io/scenes/SceneGenerators.h"
#include "raster/FrameError.h"
#include "raster/Renderer.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

// Signed volume by the divergence theorem: positive when faces wind
// counter-clockwise seen from outside.
double SignedVolume(const Scene& scene) {
  double volume = 0.0;
  for (const SceneTriangle& t : scene.triangles) {
    const Vec3 a = scene.verticesWorld[t.vertices[0]], b = scene.verticesWorld[t.vertices[1]],
               c = scene.verticesWorld[t.vertices[2]];
    volume += Dot(a, Cross(b, c)) / 6.0;
  }
  return volume;
}

// Closed and consistently oriented: every directed edge has its reverse exactly once.
bool IsClosedManifold(const Scene& scene) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t f = 0; f < scene.FaceCount(); ++f) {
    const auto face = scene.Face(f);
    for (size_t i = 0; i < face.size(); ++i) ++directed[{face[i], face[(i + 1) % face.size()]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

TEST(Scenes, SolidsAreClosedAndFaceOutwards) {
  for (const char* name : {"cube", "wedge", "letter_l", "beams", "sphere_cone", "steps"}) {
    const Scene scene = test::LoadScene(std::string("data/") + name + ".dat");
    EXPECT_TRUE(IsClosedManifold(scene)) << name;
    EXPECT_GT(SignedVolume(scene), 0.0) << name;
  }
}

TEST(Scenes, SizesAreAsDocumented) {
  const Scene sphereCone = test::LoadScene("data/sphere_cone.dat");
  EXPECT_NEAR(static_cast<double>(sphereCone.verticesWorld.size()), 1800, 50);
  EXPECT_NEAR(static_cast<double>(sphereCone.FaceCount()), 1900, 50);
  EXPECT_DOUBLE_EQ(SignedVolume(test::LoadScene("data/cube.dat")), 1.0);
  EXPECT_DOUBLE_EQ(SignedVolume(test::LoadScene("data/wedge.dat")), 7.5);
}

TEST(Scenes, FunctionSurfaceIsTwoSided) {
  const Scene surface = test::LoadScene("data/surface.dat");
  ASSERT_EQ(surface.FaceCount() % 2, 0U);
  for (size_t f = 0; f + 1 < surface.FaceCount(); f += 2) {
    const Vec3 n = surface.facePlanesWorld[f].normal, m = surface.facePlanesWorld[f + 1].normal;
    EXPECT_NEAR(Dot(n, m), -1.0, 1e-12);
  }
  EXPECT_NEAR(SignedVolume(surface), 0.0, 1e-9);
}

TEST(Scenes, OnlyConvexClosedSolidsLetAutoCullAlone) {
  for (const char* name : {"cube", "wedge"}) {
    EXPECT_TRUE(test::LoadScene(std::string("data/") + name + ".dat").convexClosedSolid) << name;
  }
  // Non-convex solids, several solids, sheets: auto keeps the Z-buffer.
  for (const char* name : {"letter_l", "steps", "beams", "sphere_cone", "surface"}) {
    EXPECT_FALSE(test::LoadScene(std::string("data/") + name + ".dat").convexClosedSolid) << name;
  }
  EXPECT_TRUE(PrepareScene(GenerateSphere(20, 30)).convexClosedSolid);
  EXPECT_EQ(ResolvedMethod(test::LoadScene("data/cube.dat"), Method::kAuto), Method::kCull);
  EXPECT_EQ(ResolvedMethod(test::LoadScene("data/beams.dat"), Method::kAuto), Method::kZBuffer);
}

TEST(Scenes, AutoIsExactWhereItCullsAlone) {
  const Scene sphere = PrepareScene(GenerateSphere(40, 60));
  RenderOptions options;
  options.method = Method::kAuto;
  for (bool keepDepth : {true, false}) {  // without depth, as the viewer draws
    options.keepDepth = keepDepth;
    for (double theta : {0.3, 1.9, 4.0}) {
      const test::Frame frame = test::RenderFrame(sphere, theta, 0.8, 100, 40, options);
      const FaceErrorReport report = MeasureFaceError(sphere, frame.camera, true, frame.cells);
      EXPECT_EQ(report.wrongCells, 0);
      EXPECT_GT(report.comparedCells, 500);
    }
  }
}

// The viewer and text dumps skip depth where no method needs it; no cell may change.
TEST(Scenes, DroppingDepthChangesNoCell) {
  for (const char* name : {"cube", "beams", "letter_l", "surface", "steps"}) {
    const Scene scene = test::LoadScene(std::string("data/") + name + ".dat");
    for (Method method :
         {Method::kZBuffer, Method::kPainter, Method::kCull, Method::kWire, Method::kAuto}) {
      RenderOptions withDepth, withoutDepth;
      withDepth.method = withoutDepth.method = method;
      withoutDepth.keepDepth = false;
      for (double theta : {0.3, 2.2}) {
        const test::Frame kept = test::RenderFrame(scene, theta, 1.1, 90, 30, withDepth);
        const test::Frame dropped = test::RenderFrame(scene, theta, 1.1, 90, 30, withoutDepth);
        EXPECT_EQ(dropped.cells.FaceNumbers(), kept.cells.FaceNumbers())
            << name << ' ' << MethodName(method);
        EXPECT_EQ(dropped.Text(), kept.Text()) << name << ' ' << MethodName(method);
      }
    }
  }
}

TEST(Scenes, NonConvexFacesTriangulateToNMinusTwo) {
  const Scene letter = test::LoadScene("data/letter_l.dat");
  // Two L hexagons (4 triangles each) and six side quads (2 each).
  EXPECT_EQ(letter.triangles.size(), 2U * 4U + 6U * 2U);
}

}  // namespace
}  // namespace termshade
