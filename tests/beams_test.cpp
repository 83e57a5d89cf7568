// Three beams in cyclic overlap: no back-to-front order exists. The Z-buffer's
// JSON dump matches the exact ray cast at every cell outside the don't-care
// band; the textbook painter's algorithm visibly does not.
#include <gtest/gtest.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "geometry/RayCast.h"
#include "geometry/ViewingTransform.h"
#include "io/write/FrameFormats.h"
#include "raster/FrameError.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

struct DumpComparison {
  int compared = 0;
  int wrong = 0;
};

// Parses the json dump and compares its face map with the reference.
DumpComparison CompareJsonDump(const Scene& scene, Method method, double theta, double phi) {
  RenderOptions options;
  options.method = method;
  const test::Frame frame = test::RenderFrame(scene, theta, phi, 100, 40, options);
  std::string text;
  AppendJsonFrame(frame.cells, frame.depth, scene, frame.camera, options, text);
  const nlohmann::json dump = nlohmann::json::parse(text);
  EXPECT_EQ(dump["format"], "termshade-frame/1");
  EXPECT_EQ(dump["method"], std::string(MethodName(method)));

  // eyeFromFile takes file coordinates where the pipeline takes them.
  const auto& m = dump["camera"]["eyeFromFile"];
  const Mat4 eyeFromWorld = EyeFromWorld(frame.camera.view);
  for (size_t v = 0; v < scene.verticesWorld.size(); ++v) {
    const Vec3 p = scene.VertexFile(v);
    const Vec3 expected = TransformPoint(eyeFromWorld, scene.verticesWorld[v]);
    for (int row = 0; row < 3; ++row) {
      const double actual = double(m[4 * row]) * p.x + double(m[4 * row + 1]) * p.y +
                            double(m[4 * row + 2]) * p.z + double(m[4 * row + 3]);
      // 12 significant digits (FrameFormats.h): the same dump on every CPU.
      EXPECT_NEAR(actual, row == 0 ? expected.x : (row == 1 ? expected.y : expected.z), 1e-9);
    }
  }

  // Rebuild the camera from the dump alone, as an outside tool would.
  Camera camera = frame.camera;
  camera.projection.d = dump["camera"]["d"];
  camera.projection.cx = dump["camera"]["center"][0];
  camera.projection.cy = dump["camera"]["center"][1];
  const ReferenceRayCaster reference(scene, camera, true);
  DumpComparison result;
  for (int row = 0; row < dump["rows"]; ++row) {
    for (int col = 0; col < dump["cols"]; ++col) {
      const double u = col + 0.5, v = row + 0.5;
      const RaySample exact = reference.Cast(u, v);
      const uint32_t dumped = dump["faces"][row][col];
      if (reference.DistanceToFaceEdgeCells(exact.faceNumber, u, v) <= kEdgeBandCells ||
          reference.DistanceToFaceEdgeCells(dumped, u, v) <= kEdgeBandCells) {
        continue;
      }
      ++result.compared;
      if (dumped != exact.faceNumber) ++result.wrong;
      if (dumped != 0 && dumped == exact.faceNumber) {
        // Depth agrees up to what snapping vertices to 1/256 cell moves a
        // surface (its w gradient times the snap) and float rounding.
        const double wDumped = 1.0 / static_cast<double>(dump["depth"][row][col]);
        const double wExact = 1.0 / exact.depth;
        const double tolerance =
            reference.WGradientPerCell(dumped) * kEdgeBandCells + 1e-6 * wExact;
        EXPECT_NEAR(wDumped, wExact, tolerance) << col << "," << row;
      }
    }
  }
  return result;
}

constexpr double kViews[][2] = {{0.3, 0.35}, {1.0, 0.2}, {2.5, 0.5}, {-0.7, 0.1}};

TEST(Beams, ZBufferDumpMatchesTheExactRayCastEverywhere) {
  const Scene scene = test::LoadScene("data/beams.dat");
  for (const auto& view : kViews) {
    const DumpComparison zbuffer = CompareJsonDump(scene, Method::kZBuffer, view[0], view[1]);
    EXPECT_GT(zbuffer.compared, 500);
    EXPECT_EQ(zbuffer.wrong, 0) << "theta " << view[0] << " phi " << view[1];
  }
}

TEST(Beams, PainterVisiblyFailsOnCyclicOverlap) {
  const Scene scene = test::LoadScene("data/beams.dat");
  int viewsWherePainterFails = 0;
  for (const auto& view : kViews) {
    const DumpComparison painter = CompareJsonDump(scene, Method::kPainter, view[0], view[1]);
    std::cout << "painter at theta " << view[0] << " phi " << view[1] << ": " << painter.wrong
              << " of " << painter.compared << " cells wrong\n";
    if (painter.wrong >= 10) ++viewsWherePainterFails;
  }
  // Whatever order a sort picks, one crossing of the cycle is drawn wrong.
  EXPECT_EQ(viewsWherePainterFails, 4);
}

TEST(Beams, FaceErrorMeasureAgrees) {
  const Scene scene = test::LoadScene("data/beams.dat");
  RenderOptions options;
  const test::Frame zbuffer = test::RenderFrame(scene, 0.3, 0.35, 100, 40, options);
  EXPECT_EQ(MeasureFaceError(scene, zbuffer.camera, true, zbuffer.cells).wrongCells, 0);
  options.method = Method::kPainter;
  const test::Frame painter = test::RenderFrame(scene, 0.3, 0.35, 100, 40, options);
  EXPECT_GT(MeasureFaceError(scene, painter.camera, true, painter.cells).wrongCells, 10);
}

}  // namespace
}  // namespace termshade
