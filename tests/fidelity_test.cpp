// Fidelity (SPEC 12): the measure's own properties, and a floor per glyph
// mode on one scene, so a change that makes the frames look worse fails.
#include <gtest/gtest.h>

#include <cstdio>

#include "raster/FrameFidelity.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

struct Measured {
  Fidelity fidelity;
  double range = 0.0;
};

Measured MeasureMode(const Scene& scene, GlyphMode mode, bool colour, int cols, int rows) {
  RenderOptions options;
  options.shade = ShadeMode::kLambert;
  options.glyphs = mode;
  options.twoColour = colour;
  const test::Frame frame = test::RenderFrame(scene, 0.3, 1.3, cols, rows, options);
  const double range = InkRange(options, colour, DefaultInkTable());
  const InkImage exact = ExactImage(scene, frame.camera, options, cols, rows, range);
  return {CompareImages(exact, GlyphImage(frame.cells, DefaultInkTable(), colour), range), range};
}

TEST(Fidelity, AnImageComparedWithItselfIsPerfect) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  RenderOptions options;
  const test::Frame frame = test::RenderFrame(scene, 0.3, 1.3, 20, 8, options);
  const InkImage exact = ExactImage(scene, frame.camera, options, 20, 8, 1.0);
  const Fidelity same = CompareImages(exact, exact, 1.0);
  EXPECT_EQ(same.mse, 0.0);
  EXPECT_NEAR(same.ssim, 1.0, 1e-6);
  InkImage blank = exact;
  std::fill(blank.pixels.begin(), blank.pixels.end(), 0.0F);
  EXPECT_LT(CompareImages(exact, blank, 1.0).ssim, 0.5);
}

TEST(Fidelity, InkRangesAreTheBrightestGlyphs) {
  RenderOptions options;
  EXPECT_NEAR(InkRange(options, false, DefaultInkTable()), DefaultInkTable().MeanInk(U'@'), 1e-12);
  options.glyphs = GlyphMode::kSextants;
  EXPECT_EQ(InkRange(options, true, DefaultInkTable()), 1.0);
}

// Floors: measured (sphere_cone, 48x16, default view) minus 0.02. Raise them
// when the frames get better; never lower them to make a change pass.
TEST(Fidelity, EveryModeStaysAboveItsRecordedFloor) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  struct Floor {
    GlyphMode mode;
    bool colour;
    double ssim;
  };
  const Floor floors[] = {
      {GlyphMode::kRamp, false, 0.47},      {GlyphMode::kRamp, true, 0.44},
      {GlyphMode::kAscii, false, 0.70},     {GlyphMode::kAscii, true, 0.75},
      {GlyphMode::kBlocks, false, 0.82},    {GlyphMode::kBlocks, true, 0.91},
      {GlyphMode::kQuadrants, false, 0.85}, {GlyphMode::kQuadrants, true, 0.93},
      {GlyphMode::kSextants, false, 0.88},  {GlyphMode::kSextants, true, 0.95},
      {GlyphMode::kBraille, false, 0.83},   {GlyphMode::kBraille, true, 0.95},
  };
  for (const Floor& floor : floors) {
    const Measured measured = MeasureMode(scene, floor.mode, floor.colour, 48, 16);
    std::printf("%-10s %-6s ssim %.4f mse %.6f range %.3f\n", GlyphModeName(floor.mode).data(),
                floor.colour ? "colour" : "mono", measured.fidelity.ssim, measured.fidelity.mse,
                measured.range);
    EXPECT_GE(measured.fidelity.ssim, floor.ssim)
        << GlyphModeName(floor.mode) << (floor.colour ? " with colour" : " without colour");
  }
}

}  // namespace
}  // namespace termshade
