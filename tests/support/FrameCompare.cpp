#include "support/FrameCompare.h"

#include <gtest/gtest.h>

#include <bit>

#include "geometry/FitCamera.h"

namespace termshade::test {

DrawnFrame DrawOrbit(Renderer& renderer, const Scene& scene, const OrbitView& view, int width,
                     int height, const RenderOptions& options) {
  ViewParams params = DefaultView(scene.diagonalModelUnits);
  params.theta = view.theta;
  params.phi = view.phi;
  params.rho *= view.rhoScale;
  const Camera camera = FitCamera(scene, params, width, height, 2.0);
  DrawnFrame drawn;
  drawn.cells.Resize(width, height);
  drawn.depth.Resize(width, height);
  drawn.stats = renderer.Render(scene, camera, options, drawn.depth, drawn.cells);
  return drawn;
}

void ExpectSameFrame(const DrawnFrame& expected, const DrawnFrame& actual,
                     const std::string& what) {
  ASSERT_EQ(expected.cells.FaceNumbers(), actual.cells.FaceNumbers()) << what;
  ASSERT_EQ(expected.cells.Glyphs(), actual.cells.Glyphs()) << what;
  const size_t count = expected.cells.FaceNumbers().size();
  for (size_t i = 0; i < count; ++i) {
    ASSERT_EQ(std::bit_cast<uint32_t>(expected.depth.At(i)),
              std::bit_cast<uint32_t>(actual.depth.At(i)))
        << what << ": depth of cell " << i;
  }
  // Rays count the (sample, triangle) pairs they find, not triangles set up.
  if (!expected.stats.byHierarchy && !actual.stats.byHierarchy) {
    EXPECT_EQ(expected.stats.trianglesDrawn, actual.stats.trianglesDrawn) << what;
  }
  EXPECT_EQ(expected.stats.facesVisible, actual.stats.facesVisible) << what;
}

}  // namespace termshade::test
