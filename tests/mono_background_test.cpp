// Mono frames on a light background (issue 33, item 1): the ink is the
// terminal's dark foreground, so each face's glyph follows its darkness: the
// brightest face gets the least ink. Colour frames keep their glyphs (their
// colours carry the background).
#include <gtest/gtest.h>

#include <map>

#include "geometry/FitCamera.h"
#include "raster/Renderer.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

// Each face's ramp level in a frame of the cube (three faces seen).
std::map<uint32_t, int> FaceLevels(Background background, bool colour, ShadeMode shade) {
  const Scene scene = test::LoadScene("data/cube.dat");
  const Camera camera =
      FitCamera(scene, {DefaultView(scene.diagonalModelUnits).rho, 0.7, 1.1}, 60, 20, 2.0);
  RenderOptions options;
  options.background = background;
  options.twoColour = colour;
  options.shade = shade;
  CellBuffer cells(60, 20);
  DepthBuffer depth;
  depth.Resize(60, 20);
  Renderer renderer;
  renderer.Render(scene, camera, options, depth, cells);
  std::map<uint32_t, int> levels;
  for (int row = 0; row < 20; ++row) {
    for (int col = 0; col < 60; ++col) {
      if (cells.FaceNumber(col, row) != 0)
        levels[cells.FaceNumber(col, row)] = cells.Level(col, row);
    }
  }
  return levels;
}

TEST(MonoBackground, OnALightBackgroundTheBrightestFaceGetsTheLeastInk) {
  for (const ShadeMode shade : {ShadeMode::kContrast, ShadeMode::kLambert}) {
    const auto dark = FaceLevels(Background::kDark, false, shade);
    const auto light = FaceLevels(Background::kLight, false, shade);
    ASSERT_EQ(dark.size(), 3U) << "three faces of the cube seen";
    ASSERT_EQ(light.size(), 3U);
    // The faces' order by ink reverses.
    for (const auto& [a, levelA] : dark) {
      for (const auto& [b, levelB] : dark) {
        if (levelA > levelB) {
          EXPECT_LT(light.at(a), light.at(b)) << a << " vs " << b;
        }
      }
    }
  }
}

TEST(MonoBackground, ColourFramesKeepTheirLevelsOnEitherBackground) {
  EXPECT_EQ(FaceLevels(Background::kLight, true, ShadeMode::kContrast),
            FaceLevels(Background::kDark, true, ShadeMode::kContrast));
}

}  // namespace
}  // namespace termshade
