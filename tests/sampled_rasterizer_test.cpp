// The sampled rasterizer (cell by cell, src/raster/SampledRasterizer) gives
// every sample exactly what the one-sample rasterizer gives it on a frame of
// k x m times the cells: the same faces, depth and cells, for every glyph
// mode, method, colour and view, big triangles (64-bit lanes) included, 2x4
// cells eight lanes (AVX2, where the CPU has it) and four at a time.
#include <gtest/gtest.h>

#include <numbers>

#include "geometry/FitCamera.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/Renderer.h"
#include "raster/SampledRasterizer.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

struct Frame {
  CellBuffer cells;
  DepthBuffer depth;
  CellBuffer samples;
  RenderStats stats;
};

// One renderer per path for many frames: what a frame leaves behind must not show in the next.
Frame Draw(Renderer& renderer, const Scene& scene, const Camera& camera, RenderOptions options,
           bool sampled, int cols, int rows) {
  options.variant.sampledRasterizer = sampled;
  Frame frame;
  frame.cells.Resize(cols, rows);
  frame.depth.Resize(cols, rows);
  frame.stats = renderer.Render(scene, camera, options, frame.depth, frame.cells);
  frame.samples = renderer.Samples();
  return frame;
}

void ExpectSame(const Frame& a, const Frame& b, bool depth, const std::string& what) {
  ASSERT_EQ(a.samples.FaceNumbers(), b.samples.FaceNumbers()) << what;
  EXPECT_EQ(a.cells.Glyphs(), b.cells.Glyphs()) << what;
  EXPECT_EQ(a.cells.FaceNumbers(), b.cells.FaceNumbers()) << what;
  EXPECT_EQ(a.cells.Levels(), b.cells.Levels()) << what;
  EXPECT_EQ(a.cells.Intensities(), b.cells.Intensities()) << what;
  EXPECT_EQ(a.cells.BackFaceNumbers(), b.cells.BackFaceNumbers()) << what;
  EXPECT_EQ(a.cells.BackIntensities(), b.cells.BackIntensities()) << what;
  EXPECT_EQ(a.stats.trianglesDrawn, b.stats.trianglesDrawn) << what;
  EXPECT_EQ(a.stats.facesVisible, b.stats.facesVisible) << what;
  if (!depth) return;
  for (int row = 0; row < a.cells.HeightCells(); ++row) {
    for (int col = 0; col < a.cells.WidthCells(); ++col) {
      const size_t i = a.cells.Index(col, row);
      ASSERT_EQ(a.depth.At(i), b.depth.At(i)) << what << " at " << col << "," << row;
    }
  }
}

void CompareOn(const Scene& scene, const std::string& name, int cols, int rows, double rhoScale) {
  Renderer sampledRenderer, referenceRenderer;
  for (int v = 0; v < 3; ++v) {
    ViewParams view = DefaultView(scene.diagonalModelUnits);
    view.theta += v * 2.1;
    view.phi = v == 1 ? -0.4 : 1.1;
    view.rho *= rhoScale;
    const Camera camera = FitCamera(scene, view, cols, rows, 2.0);
    for (Method method : {Method::kZBuffer, Method::kCull, Method::kAuto}) {
      for (int m = 0; m < kGlyphModeCount; ++m) {
        for (int flags = 0; flags < 4; ++flags) {
          RenderOptions options;
          options.method = method;
          options.glyphs = static_cast<GlyphMode>(m);
          options.twoColour = (flags & 1) != 0;
          options.keepDepth = (flags & 2) != 0;
          options.shade = v == 2 ? ShadeMode::kLambert : ShadeMode::kContrast;
          if (options.glyphs == GlyphMode::kRamp) options.variant.samples = {2, 4};
          const std::string what =
              name + " view " + std::to_string(v) + " " + std::string(MethodName(method)) + " " +
              std::string(GlyphModeName(options.glyphs)) + " flags " + std::to_string(flags) + " " +
              std::to_string(cols) + "x" + std::to_string(rows);
          const Frame reference =
              Draw(referenceRenderer, scene, camera, options, false, cols, rows);
          ExpectSame(Draw(sampledRenderer, scene, camera, options, true, cols, rows), reference,
                     options.keepDepth, what);
          if (FrameSampleGrid(options) ==
              SampleGrid{2, 4}) {  // the four-lane path of 2x4 cells too
            options.variant.wideLanes = false;
            ExpectSame(Draw(sampledRenderer, scene, camera, options, true, cols, rows), reference,
                       options.keepDepth, what + " four lanes");
          }
        }
      }
    }
  }
}

// The comparisons above take the eight-lane path only where the CPU has
// AVX2; elsewhere this test shows as skipped, so a run that never exercised
// that path says so.
TEST(SampledRasterizer, EightLanePathIsExercisedHere) {
  if (!SampledRasterizer::WideAvailable()) GTEST_SKIP() << "no AVX2: only the four-lane path ran";
}

TEST(SampledRasterizer, EverySampleAsTheOneSampleRasterizerOnShippedScenes) {
  for (const std::string& name : GeneratedSceneNames()) {
    const Scene scene = test::LoadScene("data/" + name + ".dat");
    CompareOn(scene, name, 48, 16, 1.0);
    CompareOn(scene, name, 97, 31, 1.0);
  }
}

TEST(SampledRasterizer, ARendererMovedToAnotherSceneDrawsAsAFreshOne) {
  // What one scene's frames leave in a renderer (face tables sized for its faces) must not
  // show in another's, whichever has more faces.
  std::vector<Scene> scenes;
  for (const std::string& name : GeneratedSceneNames()) {
    scenes.push_back(test::LoadScene("data/" + name + ".dat"));
  }
  for (int m = 0; m < kGlyphModeCount; ++m) {
    RenderOptions options;
    options.glyphs = static_cast<GlyphMode>(m);
    Renderer moved;
    for (const Scene& first : scenes) {
      for (const Scene& second : scenes) {
        const Camera firstCamera =
            FitCamera(first, DefaultView(first.diagonalModelUnits), 48, 16, 2.0);
        const Camera camera =
            FitCamera(second, DefaultView(second.diagonalModelUnits), 48, 16, 2.0);
        Draw(moved, first, firstCamera, options, true, 48, 16);
        Renderer fresh;
        ExpectSame(Draw(moved, second, camera, options, true, 48, 16),
                   Draw(fresh, second, camera, options, true, 48, 16), false,
                   std::string(GlyphModeName(options.glyphs)));
      }
    }
  }
}

TEST(SampledRasterizer, BigTrianglesAndTheEyeCloseUp) {
  // Close up, triangles span hundreds of samples (64-bit lanes) and cross the near plane.
  for (const std::string& name : {std::string("cube"), std::string("sphere_cone")}) {
    const Scene scene = test::LoadScene("data/" + name + ".dat");
    CompareOn(scene, name, 160, 48, 0.35);
  }
}

}  // namespace
}  // namespace termshade
