// Glyph modes (SPEC 11): patterns read back from the measured glyphs, the
// samples' geometry, per-sample face error, and the json samples.
#include <gtest/gtest.h>

#include <array>
#include <nlohmann/json.hpp>
#include <set>

#include "geometry/FitCamera.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/FrameFormats.h"
#include "raster/FrameError.h"
#include "raster/FramePlan.h"
#include "raster/Renderer.h"
#include "shade/BlockGlyphs.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/GlyphInk.h"
#include "shade/OrderedDither.h"
#include "shade/ShadeGlyph.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

constexpr GlyphMode kPatternModes[] = {GlyphMode::kBlocks, GlyphMode::kQuadrants,
                                       GlyphMode::kSextants, GlyphMode::kBraille};
constexpr GlyphMode kAllModes[] = {GlyphMode::kRamp,     GlyphMode::kAscii,
                                   GlyphMode::kBlocks,   GlyphMode::kQuadrants,
                                   GlyphMode::kSextants, GlyphMode::kBraille};

// The pattern a glyph shows, read from its measured ink map: a region counts
// as inked when its mean ink passes a quarter (braille dots cover about 28% of theirs).
SamplePattern PatternOfGlyph(char32_t glyph, SampleGrid grid) {
  const InkMap* ink = DefaultInkTable().Find(glyph);
  if (ink == nullptr) return ~SamplePattern{0};
  SamplePattern pattern = 0;
  for (int n = 0; n < grid.Count(); ++n) {
    const int i = n % grid.across, j = n / grid.across;
    int sum = 0, area = 0;
    for (int y = j * kInkRows / grid.down; y < (j + 1) * kInkRows / grid.down; ++y) {
      for (int x = i * kInkColumns / grid.across; x < (i + 1) * kInkColumns / grid.across; ++x) {
        sum += (*ink)[static_cast<size_t>(y * kInkColumns + x)];
        ++area;
      }
    }
    if (sum > area * 48) pattern |= SamplePattern{1} << n;
  }
  return pattern;
}

SamplePattern CoverageOfCell(const CellBuffer& samples, SampleGrid grid, int col, int row) {
  SamplePattern pattern = 0;
  for (int n = 0; n < grid.Count(); ++n) {
    const int i = n % grid.across, j = n / grid.across;
    if (samples.FaceNumber(col * grid.across + i, row * grid.down + j) != 0) {
      pattern |= SamplePattern{1} << n;
    }
  }
  return pattern;
}

struct ModeFrame {
  Camera camera;
  CellBuffer cells;
  DepthBuffer depth;
  CellBuffer samples;
  SampleGrid grid;
};

ModeFrame RenderMode(const Scene& scene, GlyphMode mode, int cols, int rows, double aspect = 2.0,
                     bool twoColour = false) {
  ModeFrame frame;
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  frame.camera = FitCamera(scene, view, cols, rows, aspect);
  frame.cells.Resize(cols, rows);
  frame.depth.Resize(cols, rows);
  RenderOptions options;
  options.glyphs = mode;
  options.twoColour = twoColour;
  Renderer renderer;
  renderer.Render(scene, frame.camera, options, frame.depth, frame.cells);
  frame.grid = renderer.LastSampleGrid();
  frame.samples = frame.grid.Count() > 1 ? renderer.Samples() : frame.cells;
  return frame;
}

TEST(PatternGlyphs, EveryPatternHasItsOwnMeasuredGlyphShowingIt) {
  for (GlyphMode mode : kPatternModes) {
    const SampleGrid grid = ModeSampleGrid(mode);
    std::set<char32_t> seen;
    for (SamplePattern pattern = 0; pattern < (SamplePattern{1} << grid.Count()); ++pattern) {
      const char32_t glyph = PatternGlyph(mode, pattern);
      seen.insert(glyph);
      ASSERT_NE(DefaultInkTable().Find(glyph), nullptr) << std::hex << uint32_t{glyph};
      EXPECT_EQ(PatternOfGlyph(glyph, grid), pattern)
          << GlyphModeName(mode) << " pattern " << pattern << " glyph U+" << std::hex
          << uint32_t{glyph};
    }
    EXPECT_EQ(seen.size(), size_t{1} << grid.Count()) << GlyphModeName(mode);
  }
}

TEST(GlyphInkTables, SortedAndHoldingPrintableAscii) {
  for (const GlyphInkTable* table : {&DefaultInkTable(), &UnifontInkTable()}) {
    for (size_t i = 1; i < table->glyphs.size(); ++i) {
      EXPECT_LT(table->glyphs[i - 1].codePoint, table->glyphs[i].codePoint) << table->fontName;
    }
    for (char32_t c = U' '; c <= U'~'; ++c) EXPECT_NE(table->Find(c), nullptr) << char(c);
    EXPECT_EQ(table->MeanInk(U' '), 0.0);
    EXPECT_EQ(table->MeanInk(U'\u2588'), 1.0) << table->fontName;
  }
}

// Without colour braille dithers: a covered sample is inked where its shade
// exceeds the screen-fixed threshold there, and a covered cell keeps at least
// one sample (its lowest threshold's) inked. In blocks, quadrants and
// sextants a cell whose samples are all covered is the shade glyph (a bar) of
// their mean shade, and a silhouette cell the glyph nearest its samples after
// a blur.
TEST(GlyphModes, WithoutColourTheGlyphFollowsTheSamplesShades) {
  for (const std::string& name : GeneratedSceneNames()) {
    const Scene scene = test::LoadScene("data/" + name + ".dat");
    for (GlyphMode mode : kPatternModes) {
      const ModeFrame frame = RenderMode(scene, mode, 60, 20);
      RenderOptions options;
      options.glyphs = mode;
      const OrderedDither dither(PlanGlyphs(options).ditherOrder);
      const BlurredGlyphMatch matcher(mode, frame.grid);
      // The samples' shades: the one-sample frame at the sample camera (its faces are the
      // samples').
      RenderOptions single;
      single.variant.samples = {1, 1};
      CellBuffer fine(60 * frame.grid.across, 20 * frame.grid.down);
      DepthBuffer fineDepth;
      fineDepth.Resize(fine.WidthCells(), fine.HeightCells());
      Renderer().Render(scene, SampleCamera(frame.camera, frame.grid), single, fineDepth, fine);
      int partlyInked = 0, shaded = 0, matched = 0;
      const SamplePattern all = (SamplePattern{1} << frame.grid.Count()) - 1;
      for (int row = 0; row < 20; ++row) {
        for (int col = 0; col < 60; ++col) {
          const SamplePattern covered = CoverageOfCell(frame.samples, frame.grid, col, row);
          std::array<uint8_t, 8> values{};
          for (int n = 0; n < frame.grid.Count(); ++n) {
            const int x = col * frame.grid.across + n % frame.grid.across;
            const int y = row * frame.grid.down + n / frame.grid.across;
            ASSERT_EQ(fine.FaceNumber(x, y), frame.samples.FaceNumber(x, y));
            values[n] = fine.Intensity(x, y);
          }
          if (mode != GlyphMode::kBraille && covered == all) {
            int sum = 0;
            for (int n = 0; n < frame.grid.Count(); ++n) sum += values[n];
            const int count = frame.grid.Count();
            ASSERT_EQ(frame.cells.Glyph(col, row),
                      ShadeGlyph(static_cast<uint8_t>((sum + count / 2) / count)))
                << name << " " << GlyphModeName(mode) << " cell " << col << "," << row;
            ++shaded;
            continue;
          }
          if (mode != GlyphMode::kBraille) {
            if (covered == 0) continue;
            ASSERT_EQ(frame.cells.Glyph(col, row), matcher.Nearest(values.data()))
                << name << " " << GlyphModeName(mode) << " cell " << col << "," << row;
            ++matched;
            continue;
          }
          const SamplePattern shown = PatternOfGlyph(frame.cells.Glyph(col, row), frame.grid);
          ASSERT_EQ(shown, dither.CellInk(values.data(), covered, frame.grid, col, row))
              << name << " " << GlyphModeName(mode) << " cell " << col << "," << row;
          ASSERT_EQ(shown & ~covered, 0U);
          ASSERT_EQ(shown != 0, covered != 0);
          partlyInked += shown != covered ? 1 : 0;
        }
      }
      EXPECT_EQ(partlyInked > 0, mode == GlyphMode::kBraille) << name << " " << GlyphModeName(mode);
      EXPECT_EQ(shaded > 0, mode != GlyphMode::kBraille) << name << " " << GlyphModeName(mode);
      EXPECT_EQ(matched > 0, mode != GlyphMode::kBraille) << name << " " << GlyphModeName(mode);
    }
  }
}

TEST(GlyphModes, BlocksAreAOneSampleFrameOfTwiceTheRowsAtHalfTheAspect) {
  for (const std::string& name : GeneratedSceneNames()) {
    const Scene scene = test::LoadScene("data/" + name + ".dat");
    for (double aspect : {2.0, 1.8}) {
      const ModeFrame blocks = RenderMode(scene, GlyphMode::kBlocks, 50, 16, aspect);
      const ModeFrame fine = RenderMode(scene, GlyphMode::kRamp, 50, 32, aspect / 2);
      for (int row = 0; row < 16; ++row) {
        for (int col = 0; col < 50; ++col) {
          const SamplePattern expected = (fine.cells.FaceNumber(col, 2 * row) != 0 ? 1U : 0U) |
                                         (fine.cells.FaceNumber(col, 2 * row + 1) != 0 ? 2U : 0U);
          ASSERT_EQ(CoverageOfCell(blocks.samples, {1, 2}, col, row), expected)
              << name << " aspect " << aspect << " cell " << col << "," << row;
        }
      }
    }
  }
}

TEST(GlyphModes, EverySampleShowsTheExactlyNearestFace) {
  for (const std::string& name : GeneratedSceneNames()) {
    const Scene scene = test::LoadScene("data/" + name + ".dat");
    for (GlyphMode mode : kAllModes) {
      const ModeFrame frame = RenderMode(scene, mode, 40, 12);
      const FaceErrorReport report =
          MeasureFaceError(scene, SampleCamera(frame.camera, frame.grid), true, frame.samples);
      EXPECT_GT(report.comparedCells, 0);
      EXPECT_EQ(report.wrongCells, 0) << name << " " << GlyphModeName(mode);
    }
  }
}

TEST(GlyphModes, BlankExactlyWhereNoSampleIsCovered) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  for (GlyphMode mode : kAllModes) {
    for (bool twoColour : {false, true}) {
      const ModeFrame frame = RenderMode(scene, mode, 60, 20, 2.0, twoColour);
      for (int row = 0; row < 20; ++row) {
        for (int col = 0; col < 60; ++col) {
          const bool covered = CoverageOfCell(frame.samples, frame.grid, col, row) != 0;
          EXPECT_EQ(frame.cells.Glyph(col, row) != U' ', covered)
              << GlyphModeName(mode) << " cell " << col << "," << row;
        }
      }
    }
  }
}

TEST(GlyphModes, TwoColourSplitInksTheBrighterSide) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  for (GlyphMode mode : {GlyphMode::kBlocks, GlyphMode::kQuadrants, GlyphMode::kSextants}) {
    const ModeFrame frame = RenderMode(scene, mode, 60, 20, 2.0, true);
    int split = 0;
    for (int row = 0; row < 20; ++row) {
      for (int col = 0; col < 60; ++col) {
        if (frame.cells.Glyph(col, row) == U' ') continue;
        EXPECT_GE(frame.cells.Intensity(col, row), frame.cells.BackIntensity(col, row));
        split += frame.cells.BackFaceNumber(col, row) != 0 ? 1 : 0;
      }
    }
    EXPECT_GT(split, 0) << GlyphModeName(mode) << ": no cell shows two faces";
  }
}

// With colour, blocks sample each half 2 x 2 times and show each half's mean:
// fg and bg are the means of the samples on either side of the glyph.
TEST(GlyphModes, ColourBlocksShowEachHalfsMeanIntensity) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  constexpr int kCols = 60, kRows = 20;
  const ModeFrame frame = RenderMode(scene, GlyphMode::kBlocks, kCols, kRows, 2.0, true);
  ASSERT_EQ(frame.grid, (SampleGrid{2, 4}));
  // Each sample's intensity: a one-sample frame on the sample grid.
  CellBuffer fine(kCols * 2, kRows * 4);
  DepthBuffer fineDepth;
  fineDepth.Resize(kCols * 2, kRows * 4);
  Renderer renderer;
  renderer.Render(scene, SampleCamera(frame.camera, frame.grid), RenderOptions{}, fineDepth, fine);
  int averaged = 0;
  for (int row = 0; row < kRows; ++row) {
    for (int col = 0; col < kCols; ++col) {
      std::array<int, 2> sum{}, low{255, 255}, high{0, 0};
      for (int n = 0; n < 8; ++n) {
        const int x = col * 2 + n % 2, y = row * 4 + n / 2;
        ASSERT_EQ(fine.FaceNumber(x, y), frame.samples.FaceNumber(x, y));
        const int value = fine.FaceNumber(x, y) != 0 ? fine.Intensity(x, y) : 0;
        sum[n / 4] += value;
        low[n / 4] = std::min(low[n / 4], value);
        high[n / 4] = std::max(high[n / 4], value);
      }
      const char32_t glyph = frame.cells.Glyph(col, row);
      if (glyph != U'\u2580' && glyph != U'\u2584') continue;
      const int ink = glyph == U'\u2580' ? 0 : 1;
      const double inkMean = sum[ink] / 4.0, otherMean = sum[1 - ink] / 4.0;
      EXPECT_NEAR(frame.cells.Intensity(col, row), inkMean, 0.5) << col << "," << row;
      EXPECT_NEAR(frame.cells.BackIntensity(col, row), otherMean, 0.5) << col << "," << row;
      averaged += low[ink] < high[ink] ? 1 : 0;
    }
  }
  EXPECT_GT(averaged, 0) << "no half mixed two tones: the test shows nothing";
}

TEST(GlyphModes, JsonCarriesEachCellsSampleFaces) {
  const Scene scene = test::LoadScene("data/beams.dat");
  for (GlyphMode mode : {GlyphMode::kAscii, GlyphMode::kSextants}) {
    const ModeFrame frame = RenderMode(scene, mode, 30, 10);
    const ModeFrame center = RenderMode(scene, GlyphMode::kRamp, 30, 10);
    RenderOptions options;
    options.glyphs = mode;
    const JsonSamples samples{frame.grid, frame.samples, center.cells, center.depth};
    std::string text;
    AppendJsonFrame(frame.cells, frame.depth, scene, frame.camera, options, text, &samples);
    const auto json = nlohmann::json::parse(text);
    EXPECT_EQ(json["glyphMode"], std::string(GlyphModeName(mode)));
    EXPECT_EQ(json["samples"][0], frame.grid.across);
    EXPECT_EQ(json["samples"][1], frame.grid.down);
    for (int row = 0; row < 10; ++row) {
      for (int col = 0; col < 30; ++col) {
        const auto& faces = json["sampleFaces"][row][col];
        ASSERT_EQ(faces.size(), static_cast<size_t>(frame.grid.Count()));
        for (int n = 0; n < frame.grid.Count(); ++n) {
          EXPECT_EQ(faces[n],
                    frame.samples.FaceNumber(col * frame.grid.across + n % frame.grid.across,
                                             row * frame.grid.down + n / frame.grid.across));
        }
        EXPECT_EQ(json["faces"][row][col], center.cells.FaceNumber(col, row));
      }
    }
  }
}

TEST(GlyphModes, AsciiIsRepeatableAndIndependentOfTheCache) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  RenderOptions options;
  options.glyphs = GlyphMode::kAscii;
  const std::string once = test::RenderFrame(scene, 0.7, 1.1, 80, 24, options).Text();
  // A renderer that has drawn other views first (its cache full of other cells) agrees.
  Renderer renderer;
  CellBuffer cells(80, 24);
  DepthBuffer depth;
  depth.Resize(80, 24);
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  for (double theta : {0.1, 2.0, 4.0, 0.7}) {
    view.theta = theta;
    view.phi = 1.1;
    renderer.Render(scene, FitCamera(scene, view, 80, 24, 2.0), options, depth, cells);
  }
  std::string again;
  AppendTextFrame(cells, again);
  EXPECT_EQ(once, again);
}

}  // namespace
}  // namespace termshade

namespace termshade {
namespace {

TEST(GlyphModes, TheViewerPicksWhatTheTerminalCanDraw) {
  EXPECT_EQ(PickGlyphMode(false, true, "xterm-kitty", ""), GlyphMode::kAscii);
  EXPECT_EQ(PickGlyphMode(true, false, "xterm-kitty", ""), GlyphMode::kAscii);
  EXPECT_EQ(PickGlyphMode(true, true, "xterm-kitty", ""), GlyphMode::kSextants);
  EXPECT_EQ(PickGlyphMode(true, true, "foot", ""), GlyphMode::kSextants);
  EXPECT_EQ(PickGlyphMode(true, true, "xterm-256color", "WezTerm"), GlyphMode::kSextants);
  EXPECT_EQ(PickGlyphMode(true, true, "xterm-256color", "Apple_Terminal"), GlyphMode::kQuadrants);
  EXPECT_EQ(PickGlyphMode(true, true, "tmux-256color", ""), GlyphMode::kQuadrants);
}

TEST(GlyphModes, CyclingVisitsEveryModeOnce) {
  std::set<GlyphMode> seen;
  GlyphMode mode = GlyphMode::kRamp;
  for (int i = 0; i < kGlyphModeCount; ++i, mode = NextGlyphMode(mode)) {
    seen.insert(mode);
    EXPECT_EQ(ParseGlyphMode(GlyphModeName(mode)), mode);
  }
  EXPECT_EQ(mode, GlyphMode::kRamp);
  EXPECT_EQ(seen.size(), size_t{kGlyphModeCount});
  EXPECT_FALSE(ParseGlyphMode("sixel"));
}

}  // namespace
}  // namespace termshade
