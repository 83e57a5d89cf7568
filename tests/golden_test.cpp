// Golden text frames: every scene in data/, every method, three views.
// Set TERMSHADE_UPDATE=1 (or TERMSHADE_UPDATE_GOLDEN=1) to rewrite them after a
// deliberate change; a failure prints the diff `render --expect` prints.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "io/scenes/SceneGenerators.h"
#include "io/write/DatWriter.h"
#include "support/GoldenFile.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

using test::ReadFile;
using test::SourcePath;

struct GoldenView {
  const char* name;
  double theta;
  double phi;
};

constexpr GoldenView kViews[] = {{"default", 0.3, 1.3}, {"above", 2.1, 0.6}, {"below", -1.2, 2.2}};
constexpr Method kMethods[] = {Method::kZBuffer, Method::kPainter, Method::kCull, Method::kWire};

std::string GoldenPath(const std::string& scene, Method method, const GoldenView& view) {
  return SourcePath("tests/golden/" + scene + "." + std::string(MethodName(method)) + "." +
                    view.name + ".txt");
}

class GoldenFrames : public testing::TestWithParam<std::string> {};

TEST_P(GoldenFrames, MatchEveryMethodAndView) {
  const Scene scene = test::LoadScene("data/" + GetParam() + ".dat");
  for (Method method : kMethods) {
    for (const GoldenView& view : kViews) {
      RenderOptions options;
      options.method = method;
      const std::string actual =
          test::RenderFrame(scene, view.theta, view.phi, 80, 24, options).Text();
      test::ExpectTextGolden(GoldenPath(GetParam(), method, view), actual);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenFrames, testing::ValuesIn(GeneratedSceneNames()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// Glyph modes (SPEC 11): each mode, the default view, without and with two colours
// (the colours themselves are not in a text frame, but the split chooses the glyphs).
class GlyphGoldenFrames : public testing::TestWithParam<std::string> {};

TEST_P(GlyphGoldenFrames, MatchEveryGlyphMode) {
  const Scene scene = test::LoadScene("data/" + GetParam() + ".dat");
  for (GlyphMode mode : {GlyphMode::kAscii, GlyphMode::kBlocks, GlyphMode::kQuadrants,
                         GlyphMode::kSextants, GlyphMode::kBraille}) {
    for (bool twoColour : {false, true}) {
      if (twoColour && mode == GlyphMode::kBraille) continue;  // braille: coverage either way
      RenderOptions options;
      options.glyphs = mode;
      options.twoColour = twoColour;
      const std::string actual =
          test::RenderFrame(scene, kViews[0].theta, kViews[0].phi, 80, 24, options).Text();
      const std::string path =
          SourcePath("tests/golden/" + GetParam() + ".glyphs-" + std::string(GlyphModeName(mode)) +
                     (twoColour ? ".colour" : "") + ".txt");
      test::ExpectTextGolden(path, actual);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlyphGoldenFrames, testing::ValuesIn(GeneratedSceneNames()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(GoldenFrames, RenderingIsRepeatable) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  const RenderOptions options;
  EXPECT_EQ(test::RenderFrame(scene, 0.7, 1.1, 80, 24, options).Text(),
            test::RenderFrame(scene, 0.7, 1.1, 80, 24, options).Text());
}

TEST(ShippedScenes, DataFilesAreWhatTheGeneratorWrites) {
  for (const std::string& name : GeneratedSceneNames()) {
    EXPECT_EQ(ReadFile(SourcePath("data/" + name + ".dat")), WriteDat(*GenerateScene(name)))
        << "data/" << name << ".dat is stale: run `termshade generate all -o data`";
  }
}

}  // namespace
}  // namespace termshade
