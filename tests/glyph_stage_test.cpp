// The glyph stage's short cuts (background filled at once, uniform cells, face
// counts by sample masks, per-frame tables) against the stage as first written
// (tests/support/ReferenceGlyphStage), on random sample frames that hold far
// more mixed cells than a scene does, and on the shipped scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "geometry/FitCamera.h"
#include "geometry/ViewParams.h"
#include "raster/GlyphStage.h"
#include "raster/Renderer.h"
#include "shade/AsciiMatcher.h"
#include "support/ReferenceGlyphStage.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

constexpr int kCols = 23, kRows = 11;

// Random cells: untouched, background, one face, or a mix of a few faces
// (neighbouring face numbers, so ties and majorities both occur) and background.
SampleFrame RandomFrame(SampleGrid grid, uint32_t seed, uint32_t faceCount) {
  std::mt19937 random(seed);
  SampleFrame frame;
  frame.Begin(kCols, kRows, grid);
  const auto perCell = static_cast<size_t>(grid.Count());
  for (size_t cell = 0; cell < frame.CellCount(); ++cell) {
    const uint32_t kind = random() % 8;
    if (kind == 0) continue;  // untouched
    frame.Touch(cell);
    const uint32_t base = 1 + random() % (faceCount - 6);  // base + 5 at most: a face of the table
    for (size_t n = 0; n < perCell; ++n) {
      uint32_t face = base;
      if (kind >= 3) face = random() % 5 == 0 ? 0 : base + random() % (kind - 1);
      if (kind == 1) face = 0;
      frame.FaceData()[cell * perCell + n] = face;
      frame.DepthData()[cell * perCell + n] = face == 0 ? 0.0F : 0.01F * (1 + random() % 90);
    }
  }
  return frame;
}

std::vector<RenderOptions> EveryModeAndGrid() {
  std::vector<RenderOptions> cases;
  for (int m = 0; m < kGlyphModeCount; ++m) {
    for (bool colour : {false, true}) {
      RenderOptions options;
      options.glyphs = static_cast<GlyphMode>(m);
      options.twoColour = colour;
      cases.push_back(options);
    }
  }
  // Forced grids (the glyph stage's run-time path): ramp's mean of many samples, ascii at 4x8.
  for (SampleGrid forced : {SampleGrid{3, 5}, SampleGrid{4, 8}}) {
    for (GlyphMode mode : {GlyphMode::kRamp, GlyphMode::kAscii}) {
      RenderOptions options;
      options.glyphs = mode;
      options.variant.samples = forced;
      cases.push_back(options);
    }
  }
  return cases;
}

void ExpectSameCells(const CellBuffer& expected, const CellBuffer& actual,
                     const DepthBuffer& expectedDepth, const DepthBuffer& actualDepth,
                     const std::string& what) {
  for (int row = 0; row < expected.HeightCells(); ++row) {
    for (int col = 0; col < expected.WidthCells(); ++col) {
      const std::string at = what + " cell " + std::to_string(col) + "," + std::to_string(row);
      ASSERT_EQ(expected.Glyph(col, row), actual.Glyph(col, row)) << at;
      ASSERT_EQ(expected.FaceNumber(col, row), actual.FaceNumber(col, row)) << at;
      ASSERT_EQ(expected.Level(col, row), actual.Level(col, row)) << at;
      ASSERT_EQ(expected.Intensity(col, row), actual.Intensity(col, row)) << at;
      ASSERT_EQ(expected.BackFaceNumber(col, row), actual.BackFaceNumber(col, row)) << at;
      ASSERT_EQ(expected.BackLevel(col, row), actual.BackLevel(col, row)) << at;
      ASSERT_EQ(expected.BackIntensity(col, row), actual.BackIntensity(col, row)) << at;
      ASSERT_EQ(expectedDepth.At(expected.Index(col, row)), actualDepth.At(actual.Index(col, row)))
          << at;
    }
  }
}

TEST(GlyphStage, EqualsTheReferenceStageOnRandomSampleFrames) {
  constexpr uint32_t kFaces = 40;
  std::mt19937 random(7);
  std::vector<uint8_t> intensities(kFaces);
  for (const RenderOptions& options : EveryModeAndGrid()) {
    // One stage for every frame of a case: its tables and caches carry over.
    GlyphStage fast;
    ReferenceGlyphStage reference;
    for (uint32_t seed = 1; seed <= 12; ++seed) {
      // Intensities from few values (equal neighbours: ties in the split) or from all.
      for (uint8_t& v : intensities) {
        v = static_cast<uint8_t>(seed % 3 == 0 ? 64 * (random() % 5) - (random() % 5 == 4)
                                               : random() % 256);
      }
      const SampleFrame frame = RandomFrame(FrameSampleGrid(options), seed, kFaces);
      const GlyphStage::Samples samples{frame, intensities};
      GlyphPlan plan = PlanGlyphs(options);
      plan.writeDepth = seed % 2 == 0;
      CellBuffer expected(kCols, kRows), actual(kCols, kRows);
      DepthBuffer expectedDepth, actualDepth;
      expectedDepth.Resize(kCols, kRows);
      actualDepth.Resize(kCols, kRows);
      reference.Compose(samples, plan, expected, expectedDepth);
      fast.Compose(samples, plan, actual, actualDepth);
      ExpectSameCells(expected, actual, expectedDepth, actualDepth,
                      std::string(GlyphModeName(options.glyphs)) +
                          (options.twoColour ? " colour" : " mono") + " seed " +
                          std::to_string(seed));
      if (HasFatalFailure()) return;
    }
  }
}

// MatchShape divides by the brightest sample with a multiplication: exact for every pair.
TEST(AsciiMatcher, ShapeLevelsAreExactForEveryValueAndBrightest) {
  for (int brightest = 0; brightest < 256; ++brightest) {
    for (int value = 0; value <= brightest; ++value) {
      const std::array<uint8_t, 3> values{static_cast<uint8_t>(brightest),
                                          static_cast<uint8_t>(value), 255};
      const std::array<uint8_t, 32> levels = AsciiMatcher::ShapeLevels(values.data(), 0b011, 3);
      const int divisor = std::max(1, brightest);
      ASSERT_EQ(levels[0], std::max(1, (brightest * 15 + divisor / 2) / divisor));
      ASSERT_EQ(levels[1], std::max(1, (value * 15 + divisor / 2) / divisor))
          << value << " of " << brightest;
      ASSERT_EQ(levels[2], 0);
    }
  }
}

// 2x4 cells search four glyphs at a time: the same glyph as the plain search,
// for random sample vectors and for every one- and two-level vector (where
// ties between glyphs are most likely).
TEST(AsciiMatcher, EightSampleSearchEqualsThePlainSearch) {
  AsciiMatcher matcher;
  matcher.Prepare({2, 4});
  std::mt19937 random(7);
  auto check = [&](const std::array<uint8_t, 8>& values, uint32_t covered) {
    std::array<uint8_t, 32> inkLevels{};
    for (int n = 0; n < 8; ++n) {
      if ((covered >> n) & 1U) inkLevels[n] = static_cast<uint8_t>((values[n] * 15 + 127) / 255);
    }
    ASSERT_EQ(matcher.MatchInk(values.data(), covered), matcher.Nearest(inkLevels));
    ASSERT_EQ(matcher.MatchShape(values.data(), covered),
              matcher.Nearest(AsciiMatcher::ShapeLevels(values.data(), covered, 8)));
  };
  for (int i = 0; i < 100000; ++i) {
    std::array<uint8_t, 8> values{};
    for (uint8_t& v : values) v = static_cast<uint8_t>(random());
    check(values, random() & 0xFFU);
    if (HasFatalFailure()) return;
  }
  for (uint32_t pattern = 0; pattern < 256; ++pattern) {
    for (int low = 0; low < 256; low += 17) {
      for (int high = low; high < 256; high += 17) {
        std::array<uint8_t, 8> values{};
        for (int n = 0; n < 8; ++n)
          values[n] = static_cast<uint8_t>((pattern >> n) & 1U ? high : low);
        check(values, 0xFFU);
        check(values, pattern);
        if (HasFatalFailure()) return;
      }
    }
  }
}

TEST(GlyphStage, EqualsTheReferenceStageOnTheShippedScenes) {
  for (const char* name : {"sphere_cone", "beams", "surface"}) {
    const Scene scene = test::LoadScene(std::string("data/") + name + ".dat");
    for (RenderOptions options : EveryModeAndGrid()) {
      // The one-sample ramp frame has no glyph stage.
      if (options.variant.samples.Count() > 0 || FrameSampleGrid(options).Count() == 1) continue;
      // The renderer's frame, then the same samples through the reference stage.
      Renderer renderer;
      CellBuffer actual(61, 23), expected(61, 23);
      DepthBuffer depth, expectedDepth;
      depth.Resize(61, 23);
      expectedDepth.Resize(61, 23);
      ViewParams view = DefaultView(scene.diagonalModelUnits);
      view.theta = 0.9;
      const Camera camera = FitCamera(scene, view, 61, 23, 2.0);
      renderer.Render(scene, camera, options, depth, actual);
      // The faces' intensities as the renderer shaded them: read back from one-face cells'
      // of a ramp frame at the sample resolution.
      const SampleGrid grid = FrameSampleGrid(options);
      RenderOptions single = options;
      single.glyphs = GlyphMode::kRamp;
      single.variant.samples = {1, 1};
      CellBuffer fine(61 * grid.across, 23 * grid.down);
      DepthBuffer fineDepth;
      fineDepth.Resize(fine.WidthCells(), fine.HeightCells());
      Renderer fineRenderer;
      fineRenderer.Render(scene, SampleCamera(camera, grid), single, fineDepth, fine);
      std::vector<uint8_t> intensities(scene.FaceCount(), 0);
      for (size_t i = 0; i < fine.FaceNumbers().size(); ++i) {
        if (fine.FaceNumbers()[i] != 0) {
          intensities[fine.FaceNumbers()[i] - 1] = fine.Intensities()[i];
        }
      }
      SampleFrame frame;
      frame.Begin(61, 23, grid);
      frame.CopyFrom(fine, &fineDepth);
      ReferenceGlyphStage reference;
      reference.Compose({frame, intensities}, PlanGlyphs(options), expected, expectedDepth);
      ExpectSameCells(expected, actual, expectedDepth, depth,
                      std::string(name) + " " + std::string(GlyphModeName(options.glyphs)) +
                          (options.twoColour ? " colour" : " mono"));
      if (HasFatalFailure()) return;
    }
  }
}

}  // namespace
}  // namespace termshade
