// Snapshot tests for users' models (render --expect): the golden format read
// back, the comparison's tolerance model counted exactly, and its sensitivity.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "io/read/SnapshotGoldenReader.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/FrameDiff.h"
#include "io/write/SnapshotGoldenWriter.h"
#include "io/write/SnapshotReport.h"
#include "raster/SnapshotCompare.h"
#include "raster/SnapshotRender.h"
#include "support/GoldenFile.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

// A width x height grid: face 1 left of column `edge`, face 2 from it on, shade 10.
SnapshotSamples TwoFaces(int width, int height, int edge) {
  SnapshotSamples samples;
  samples.widthSamples = width;
  samples.heightSamples = height;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      samples.faces.push_back(x < edge ? 1 : 2);
      samples.shades.push_back(10);
    }
  }
  return samples;
}

SnapshotGolden CubeGolden(const Mesh& mesh) {
  SnapshotGolden golden;
  golden.settings.widthCells = 40;
  golden.settings.heightCells = 12;
  golden.frames = RenderSnapshot(PrepareScene(mesh), golden.settings);
  return golden;
}

TEST(SnapshotGolden, ReadsBackWhatItWrites) {
  SnapshotGolden golden = CubeGolden(test::LoadMesh("data/cube.dat"));
  golden.settings.ramp = "·░▒▓█";     // UTF-8 survives
  golden.settings.theta = 0.1 + 0.2;  // the shortest text that reads back exactly
  golden.upAxis = UpAxis::kMinusY;
  golden.frames = RenderSnapshot(PrepareScene(test::LoadMesh("data/cube.dat")), golden.settings);
  ASSERT_EQ(golden.frames.size(), 4U);
  const std::string text = FormatSnapshotGolden(golden);
  Loaded<SnapshotGolden> read = ParseSnapshotGolden(text, "cube.snap");
  ASSERT_TRUE(read.Ok()) << read.Error().ToString();
  const SnapshotGolden& back = read.Value();
  EXPECT_EQ(back.settings.theta, golden.settings.theta);
  EXPECT_EQ(back.settings.ramp, golden.settings.ramp);
  EXPECT_EQ(back.upAxis, golden.upAxis);
  EXPECT_EQ(back.settings.views, golden.settings.views);
  ASSERT_EQ(back.frames.size(), golden.frames.size());
  for (size_t i = 0; i < back.frames.size(); ++i) {
    EXPECT_EQ(back.frames[i].view.name, golden.frames[i].view.name);
    EXPECT_EQ(back.frames[i].textRows, golden.frames[i].textRows);
    EXPECT_TRUE(back.frames[i].samples == golden.frames[i].samples) << back.frames[i].view.name;
  }
  EXPECT_EQ(FormatSnapshotGolden(back), text);
  EXPECT_NE(text.find("\nview top\n|"), std::string::npos);
  EXPECT_NE(text.find("\nsize 40x12\n"), std::string::npos);
}

TEST(SnapshotGolden, ErrorsNameTheLine) {
  const std::string text = FormatSnapshotGolden(CubeGolden(test::LoadMesh("data/cube.dat")));
  const auto errorOf = [](const std::string& bytes) {
    Loaded<SnapshotGolden> read = ParseSnapshotGolden(bytes, "g.snap");
    return read.Ok() ? std::string("ok") : read.Error().ToString();
  };
  EXPECT_EQ(errorOf("P3\n"),
            "g.snap:1: not a termshade snapshot golden (the first line must be "
            "termshade-snapshot/1)");
  EXPECT_EQ(errorOf(text.substr(0, text.find("\nview top\n") + 6)),
            "g.snap:" +
                std::to_string(
                    1 + std::count(text.begin(),
                                   text.begin() + static_cast<long>(text.find("\nview top\n") + 1),
                                   '\n')) +
                ": expected `view top` (the views in the order of the header)");
  std::string badSize = text;
  badSize.replace(badSize.find("size 40x12"), 10, "size 9999x12");
  EXPECT_NE(errorOf(badSize).find(": size must be COLSxROWS, at most 4096x2048"),
            std::string::npos);
  std::string shortRow = text;
  shortRow.replace(shortRow.find("\n|") + 2, 1, "");
  EXPECT_NE(errorOf(shortRow).find("a frame row must be 40 UTF-8 characters"), std::string::npos);
  std::string hostile = text;
  hostile.replace(hostile.find("method zbuffer"), 14, "method \x1b[2J");
  EXPECT_EQ(errorOf(hostile).find('\x1b'), std::string::npos);
}

TEST(SnapshotCompare, EqualSamplesDoNotDiffer) {
  const SnapshotDifference d = CompareSnapshotSamples(TwoFaces(10, 6, 5), TwoFaces(10, 6, 5));
  EXPECT_EQ(d.modelSamples, 60);
  EXPECT_EQ(d.differingSamples, 0);
  EXPECT_EQ(d.countedSamples, 0);
  EXPECT_TRUE(d.Within(SnapshotTolerance{}));
}

TEST(SnapshotCompare, AnEdgeMovedByOneSampleIsForgiven) {
  const SnapshotDifference d = CompareSnapshotSamples(TwoFaces(10, 6, 5), TwoFaces(10, 6, 6));
  EXPECT_EQ(d.differingSamples, 6);
  EXPECT_EQ(d.edgeSamples, 6);
  EXPECT_EQ(d.countedSamples, 0);
}

TEST(SnapshotCompare, AnEdgeMovedByTwoSamplesCounts) {
  const SnapshotDifference d = CompareSnapshotSamples(TwoFaces(10, 6, 5), TwoFaces(10, 6, 7));
  EXPECT_EQ(d.differingSamples, 12);
  EXPECT_EQ(d.edgeSamples, 0);
  EXPECT_EQ(d.countedSamples, 12);
  EXPECT_EQ(d.shadeSamples, 0);
  EXPECT_FALSE(d.Within(SnapshotTolerance{}));
  EXPECT_TRUE(d.Within(SnapshotTolerance{12, false}));
  EXPECT_FALSE(d.Within(SnapshotTolerance{11, false}));
  EXPECT_TRUE(d.Within(SnapshotTolerance{20, true}));   // 20% of 60 = 12
  EXPECT_FALSE(d.Within(SnapshotTolerance{19, true}));  // 11.4 -> 11
  const std::vector<uint8_t> cells = CellsWithCountedSamples(d, {2, 3}, 5, 2);
  EXPECT_EQ(cells, (std::vector<uint8_t>{0, 0, 1, 1, 0, 0, 0, 1, 1, 0}));
}

TEST(SnapshotCompare, ShadeWithinOneStepIsEqual) {
  SnapshotSamples actual = TwoFaces(10, 6, 5);
  for (size_t i = 0; i < actual.shades.size(); ++i)
    actual.shades[i] = actual.faces[i] == 1 ? 11 : 12;
  const SnapshotDifference d = CompareSnapshotSamples(TwoFaces(10, 6, 5), actual);
  EXPECT_EQ(d.shadeStepSamples, 30);
  EXPECT_EQ(d.differingSamples, 30);
  EXPECT_EQ(d.countedSamples, 30);
  EXPECT_EQ(d.shadeSamples, 30);
}

TEST(SnapshotCompare, LoneSamplesAreForgivenPairsAreNot) {
  SnapshotSamples actual = TwoFaces(10, 6, 5);
  actual.faces[actual.Index(1, 1)] = 3;  // a face the golden does not show
  SnapshotDifference d = CompareSnapshotSamples(TwoFaces(10, 6, 5), actual);
  EXPECT_EQ(d.differingSamples, 1);
  EXPECT_EQ(d.isolatedSamples, 1);
  EXPECT_EQ(d.countedSamples, 0);
  actual.faces[actual.Index(2, 2)] = 3;  // diagonal neighbours: no longer alone
  d = CompareSnapshotSamples(TwoFaces(10, 6, 5), actual);
  EXPECT_EQ(d.differingSamples, 2);
  EXPECT_EQ(d.isolatedSamples, 0);
  EXPECT_EQ(d.countedSamples, 2);
}

TEST(SnapshotCompare, GridsOfOtherSizesDifferEverywhere) {
  const SnapshotDifference d = CompareSnapshotSamples(TwoFaces(10, 6, 5), TwoFaces(10, 5, 5));
  EXPECT_TRUE(d.sizesDiffer);
  EXPECT_FALSE(d.Within(SnapshotTolerance{100, true}));
}

TEST(SnapshotTolerance, Parses) {
  EXPECT_EQ(ParseSnapshotTolerance("12")->amount, 12.0);
  EXPECT_FALSE(ParseSnapshotTolerance("12")->percent);
  EXPECT_TRUE(ParseSnapshotTolerance("0.5%")->percent);
  EXPECT_EQ(ParseSnapshotTolerance("0.5%")->ToString(), "0.5%");
  for (const char* bad : {"", "%", "-1", "abc", "101%", "nan", "1e400", "5 "}) {
    EXPECT_FALSE(ParseSnapshotTolerance(bad)) << bad;
  }
}

// The promise of docs/snapshot-testing.md: a vertex the default view sees,
// moved by 1% of the diagonal, is caught; moved by 1e-5, never.
TEST(SnapshotCompare, CatchesOnePercentNeverOneInAHundredThousand) {
  for (const char* model : {"data/cube.dat", "data/steps.dat", "data/sphere_cone.dat"}) {
    const Mesh mesh = test::LoadMesh(model);
    const SnapshotGolden golden = CubeGolden(mesh);
    const double diagonal = PrepareScene(mesh).diagonalModelUnits;
    for (uint32_t vertex : {0U, 3U, 5U}) {
      for (const double share : {1e-5, 1e-2}) {
        Mesh moved = mesh;
        moved.verticesFile[vertex].x += share * diagonal * 0.6;
        moved.verticesFile[vertex].y -= share * diagonal * 0.8;
        const SnapshotOutcome outcome = CompareSnapshotFrames(
            golden.frames, RenderSnapshot(PrepareScene(moved), golden.settings), {});
        EXPECT_EQ(outcome.Passed(), share < 1e-3)
            << model << " vertex " << vertex << " moved by " << share << " of the diagonal";
      }
    }
  }
}

TEST(SnapshotReport, SaysWhereAndShowsTheCells) {
  const Mesh mesh = test::LoadMesh("data/cube.dat");
  const SnapshotGolden golden = CubeGolden(mesh);
  Mesh moved = mesh;
  moved.verticesFile[6].z += 0.1;
  const auto actual = RenderSnapshot(PrepareScene(moved), golden.settings);
  const SnapshotOutcome outcome = CompareSnapshotFrames(golden.frames, actual, {});
  ASSERT_FALSE(outcome.Passed());
  const std::string report =
      SnapshotReport(outcome, golden.frames, actual, golden.settings, {}, false);
  EXPECT_NE(report.find("view default: "), std::string::npos) << report;
  EXPECT_NE(report.find("DIFFERS"), std::string::npos) << report;
  EXPECT_NE(report.find('^'), std::string::npos) << report;
  EXPECT_EQ(report.find('\x1b'), std::string::npos);
  const std::string coloured =
      SnapshotReport(outcome, golden.frames, actual, golden.settings, {}, true);
  EXPECT_NE(coloured.find("\x1b[1;7;31m"), std::string::npos);
}

TEST(FrameDiff, CountsDifferingCells) {
  const TextFrameDifference same = CompareTextFrames("ab\ncd\n", "ab\ncd\n", false);
  EXPECT_EQ(same.differingCells, 0);
  EXPECT_TRUE(same.diff.empty());
  const TextFrameDifference two = CompareTextFrames("ab\ncd\nef\n", "ax\ncd\nyf\n", false);
  EXPECT_EQ(two.differingCells, 2);
  EXPECT_TRUE(two.sameShape);
  EXPECT_EQ(two.diff,
            "       goldenactual\n"  // each label over its frame's first column
            "    1 |ab|  |ax|\n"
            "        ^     ^\n"
            "    2 |cd|  |cd|\n"
            "    3 |ef|  |yf|\n"
            "       ^     ^ \n");
  EXPECT_FALSE(CompareTextFrames("ab\n", "ab\ncd\n", false).sameShape);
  EXPECT_EQ(CompareTextFrames("a\x1b\n", "ab\n", false).diff.find('\x1b'), std::string::npos);
}

// Our own snapshot goldens, one a shipped scene, checked as `render --expect`
// checks users' (the same comparison and report); TERMSHADE_UPDATE=1 rewrites them.
class GoldenSnapshots : public testing::TestWithParam<std::string> {};

TEST_P(GoldenSnapshots, MatchWithinTheDefaultTolerance) {
  SnapshotGolden actual;
  actual.settings.widthCells = 60;
  actual.settings.heightCells = 20;
  actual.settings.samples = {4, 8};  // a quarter of the default's samples: smaller files
  actual.frames = RenderSnapshot(test::LoadScene("data/" + GetParam() + ".dat"), actual.settings);
  const std::string path = test::SourcePath("tests/golden/snapshots/" + GetParam() + ".snap");
  if (test::UpdatingGoldens()) {
    std::ofstream(path, std::ios::binary) << FormatSnapshotGolden(actual);
    return;
  }
  Loaded<SnapshotGolden> golden = ReadSnapshotGolden(path);
  ASSERT_TRUE(golden.Ok()) << golden.Error().ToString();
  const SnapshotSettings& settings = golden.Value().settings;
  const auto frames = RenderSnapshot(test::LoadScene("data/" + GetParam() + ".dat"), settings);
  const SnapshotOutcome outcome = CompareSnapshotFrames(golden.Value().frames, frames, {});
  EXPECT_TRUE(outcome.Passed()) << SnapshotReport(outcome, golden.Value().frames, frames, settings,
                                                  {}, false)
                                << "(run with TERMSHADE_UPDATE=1 to accept)";
  // Exactly, too: frames hold bit for bit across builds (docs/testing.md).
  for (size_t i = 0; i < frames.size() && i < golden.Value().frames.size(); ++i) {
    EXPECT_EQ(frames[i].textRows, golden.Value().frames[i].textRows) << frames[i].view.name;
    EXPECT_TRUE(frames[i].samples == golden.Value().frames[i].samples) << frames[i].view.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenSnapshots, testing::ValuesIn(GeneratedSceneNames()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace termshade
