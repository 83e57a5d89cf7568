// Cell colours (SPEC 10): face colour x intensity over the whole range the
// terminal's background allows, the nearest entry of the 256-colour cube or
// grey ramp that stays visible on it, and the same colours in the ansi dump
// as on the screen.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "io/write/FrameFormats.h"
#include "shade/CellColour.h"
#include "shade/ColourMode.h"
#include "shade/Palette16.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

constexpr Srgb8 kBlack{0, 0, 0};
constexpr Srgb8 kWhite{255, 255, 255};
// The floor every shade keeps against its background, as a WCAG 2 contrast
// ratio: kMinBackgroundContrast less what rounding to 8 bits may take.
constexpr double kContrastFloor = kMinBackgroundContrast - 0.03;

const std::vector<Rgb>& TestColours() {
  static const std::vector<Rgb> colours{
      kDefaultFaceColour, {1, 1, 1},        {0, 0, 0},
      {1, 1, 0},          {0, 0, 1},        {1, 0, 0},
      {0, 1, 0},          {0.5F, 0.25F, 0}, {0.02F, 0.02F, 0.05F}};
  return colours;
}

TEST(CellColour, ContrastRatioIsWcags) {
  EXPECT_NEAR(ContrastRatio(kBlack, kWhite), 21.0, 1e-9);
  EXPECT_NEAR(ContrastRatio(kWhite, kWhite), 1.0, 1e-9);
  EXPECT_NEAR(RelativeLuminance({128, 128, 128}), 0.2158, 1e-4);
}

TEST(CellColour, EveryShadeStaysVisibleAgainstItsBackground) {
  for (const Background background : {Background::kDark, Background::kLight}) {
    const Srgb8 backgroundColour = background == Background::kDark ? kBlack : kWhite;
    for (const Rgb& face : TestColours()) {
      for (const ColourMode mode : {ColourMode::kTrueColour, ColourMode::k256}) {
        for (const double intensity : {0.0, 0.25, 0.5, 0.75, 1.0}) {
          const TermColour colour = CellColour(face, intensity, mode, background);
          const Srgb8 shown =
              mode == ColourMode::kTrueColour ? colour.rgb : Palette256Colour(colour.index);
          EXPECT_GE(ContrastRatio(shown, backgroundColour), kContrastFloor)
              << BackgroundName(background) << " " << face.r << " " << face.g << " " << face.b
              << " at " << intensity;
        }
      }
    }
  }
}

TEST(CellColour, ShadesSpanFromNearTheBackgroundToTheFarEnd) {
  // Dark: a white face is white when lit and close to black in shadow.
  EXPECT_EQ(ShadedFaceColour({1, 1, 1}, 1.0, Background::kDark), (Srgb8{255, 255, 255}));
  EXPECT_LE(RelativeLuminance(ShadedFaceColour({1, 1, 1}, 0.0, Background::kDark)), 0.09);
  // Light: the lit side keeps its contrast against white; the shadow is close to black.
  EXPECT_NEAR(RelativeLuminance(ShadedFaceColour({1, 1, 1}, 1.0, Background::kLight)),
              kLightCeilingLuminance, 0.005);
  EXPECT_LE(RelativeLuminance(ShadedFaceColour({1, 1, 1}, 0.0, Background::kLight)), 0.06);
  // A dark face on a dark background is lifted to the floor, never lost.
  EXPECT_NEAR(RelativeLuminance(ShadedFaceColour({0, 0, 0}, 0.0, Background::kDark)),
              kDarkFloorLuminance, 0.003);
  // The 256 colours span as far: white and near-black entries on a dark background.
  EXPECT_EQ(CellColour({1, 1, 1}, 1.0, ColourMode::k256, Background::kDark).index, 231);
  EXPECT_LE(RelativeLuminance(Palette256Colour(
                CellColour({1, 1, 1}, 0.0, ColourMode::k256, Background::kDark).index)),
            0.1);
}

TEST(CellColour, TruecolourIsFaceColourTimesIntensity) {
  // A mid-grey face: exactly face x (0.08 + 0.92 intensity) in linear light, sRGB-encoded once.
  const Rgb face{0.3F, 0.3F, 0.3F};
  const Srgb8 full = ShadedFaceColour(face, 1.0);
  EXPECT_EQ(full, (Srgb8{149, 149, 149}));  // sRGB of linear 0.3
  const Srgb8 half = ShadedFaceColour(face, 0.5);
  EXPECT_EQ(half, (Srgb8{112, 112, 112}));  // sRGB of linear 0.3 x 0.54 = 0.162
  // Hue is kept: a red face stays red, a yellow one yellow.
  const Srgb8 red = ShadedFaceColour({1, 0, 0}, 1.0);
  EXPECT_GT(red.r, 200);
  EXPECT_EQ(red.g, red.b);
  const Srgb8 yellow = ShadedFaceColour({1, 1, 0}, 0.6);
  EXPECT_EQ(yellow.r, yellow.g);
  EXPECT_LT(yellow.b, yellow.r / 2);
}

TEST(CellColour, BrighterIntensityIsNeverDarker) {
  for (const Rgb& face : TestColours()) {
    double previous = 0.0;
    for (int step = 0; step <= 20; ++step) {
      const double luminance = RelativeLuminance(ShadedFaceColour(face, step / 20.0));
      EXPECT_GE(luminance + 2.5e-3, previous);  // one 8-bit sRGB step at the dark end
      previous = luminance;
    }
  }
}

TEST(CellColour, Nearest256IsACubeOrGreyEntry) {
  EXPECT_EQ(Palette256Colour(16), (Srgb8{0, 0, 0}));
  EXPECT_EQ(Palette256Colour(196), (Srgb8{255, 0, 0}));
  EXPECT_EQ(Palette256Colour(232), (Srgb8{8, 8, 8}));
  EXPECT_EQ(Palette256Colour(244), (Srgb8{128, 128, 128}));
  // Exact palette colours visible on the background map to themselves.
  EXPECT_EQ(Nearest256Colour({128, 128, 128}), 244);
  EXPECT_EQ(Nearest256Colour({175, 95, 0}), 130);  // 16 + 36*3 + 6*1 + 0
  for (int r = 0; r < 256; r += 15) {
    for (int g = 0; g < 256; g += 15) {
      const int index = Nearest256Colour(
          {static_cast<uint8_t>(r), static_cast<uint8_t>(g), static_cast<uint8_t>(255 - r)});
      EXPECT_GE(index, 16);
      EXPECT_LE(index, 255);
    }
  }
}

TEST(CellColour, NoneIsTheTerminalsDefault) {
  EXPECT_EQ(CellColour({1, 0, 0}, 0.5, ColourMode::kNone), TermColour{});
  EXPECT_EQ(IntensityForLevel(0, 9), 0.0);
  EXPECT_EQ(IntensityForLevel(8, 9), 1.0);
  EXPECT_EQ(IntensityForLevel(0, 1), 1.0);
}

TEST(Background, ParsesAndReadsColorFgBg) {
  EXPECT_EQ(ParseBackground("dark"), Background::kDark);
  EXPECT_EQ(ParseBackground("light"), Background::kLight);
  EXPECT_FALSE(ParseBackground("black").has_value());
  EXPECT_EQ(BackgroundFromColorFgBg("15;0"), Background::kDark);
  EXPECT_EQ(BackgroundFromColorFgBg("0;15"), Background::kLight);
  EXPECT_EQ(BackgroundFromColorFgBg("0;default;7"), Background::kLight);
  EXPECT_EQ(BackgroundFromColorFgBg("12;8"), Background::kDark);
  EXPECT_FALSE(BackgroundFromColorFgBg("").has_value());
  EXPECT_FALSE(BackgroundFromColorFgBg("15;default").has_value());
  EXPECT_FALSE(BackgroundFromColorFgBg("15;99").has_value());
}

TEST(ColourMode, ParsesAndResolvesAuto) {
  EXPECT_EQ(ParseColourMode("none"), ColourMode::kNone);
  EXPECT_EQ(ParseColourMode("256"), ColourMode::k256);
  EXPECT_EQ(ParseColourMode("truecolor"), ColourMode::kTrueColour);
  EXPECT_EQ(ParseColourMode("auto"), ColourMode::kAuto);
  EXPECT_EQ(ParseColourMode("16"), ColourMode::k16);
  EXPECT_FALSE(ParseColourMode("8").has_value());
  EXPECT_EQ(AutoColourMode("1", "truecolor", 256, true), ColourMode::kNone);
  EXPECT_EQ(AutoColourMode("", "truecolor", 8, false), ColourMode::kTrueColour);
  EXPECT_EQ(AutoColourMode("", "24bit", 256, false), ColourMode::kTrueColour);
  EXPECT_EQ(AutoColourMode("", "", 256, true), ColourMode::kTrueColour);
  EXPECT_EQ(AutoColourMode("", "", 256, false), ColourMode::k256);
  EXPECT_EQ(AutoColourMode("", "", 16, false), ColourMode::k16);
  EXPECT_EQ(AutoColourMode("", "", 8, false), ColourMode::k16);  // linux, screen, ansi
  EXPECT_EQ(AutoColourMode("", "", 2, false), ColourMode::kNone);
  EXPECT_EQ(AutoColourMode("", "", -1, false), ColourMode::kNone);
}

// The cube with one red face: the ansi dump shows that face's cells red and
// the others in the default grey, at the cells' shade levels.
TEST(AnsiFrame, CarriesEachFacesColour) {
  Scene scene = test::LoadScene("data/cube.dat");
  std::vector<Rgb> colours(scene.FaceCount(), Rgb{0.2F, 0.2F, 0.9F});
  RenderOptions options;
  const test::Frame frame = test::RenderFrame(scene, 0.3, 1.3, 40, 16, options);
  const uint32_t someFace = frame.cells.FaceNumber(20, 8);
  ASSERT_GT(someFace, 0U);
  colours[someFace - 1] = Rgb{1, 0, 0};
  std::string ansi;
  AppendAnsiFrame(frame.cells, colours, options.ramp.LevelCount(), ColourMode::kTrueColour, ansi);
  const TermColour red =
      CellColour({1, 0, 0}, IntensityForLevel(frame.cells.Level(20, 8), options.ramp.LevelCount()),
                 ColourMode::kTrueColour);
  std::string redSgr;
  AppendForegroundSgr(red, redSgr);
  EXPECT_NE(ansi.find(redSgr), std::string::npos);
  EXPECT_EQ(ansi.find("48;"), std::string::npos);  // the background stays the terminal's
  // Without colours: the text frame exactly.
  std::string none, text;
  AppendAnsiFrame(frame.cells, colours, options.ramp.LevelCount(), ColourMode::kNone, none);
  AppendTextFrame(frame.cells, text);
  EXPECT_EQ(none, text);
  // With colours, stripped of SGR: the text frame too.
  EXPECT_EQ(std::regex_replace(ansi, std::regex("\x1b\\[[0-9;]*m"), ""), text);
  // A mesh without colours: every face in the default colour.
  std::string plain;
  AppendAnsiFrame(frame.cells, {}, options.ramp.LevelCount(), ColourMode::k256, plain);
  std::set<std::string> sequences;
  const std::regex sgr("\x1b\\[38;5;([0-9]+)m");
  for (auto it = std::sregex_iterator(plain.begin(), plain.end(), sgr);
       it != std::sregex_iterator(); ++it) {
    sequences.insert((*it)[1]);
  }
  std::set<std::string> expected;
  for (int level = 0; level < options.ramp.LevelCount(); ++level) {
    expected.insert(std::to_string(CellColour(kDefaultFaceColour,
                                              IntensityForLevel(level, options.ramp.LevelCount()),
                                              ColourMode::k256)
                                       .index));
  }
  for (const std::string& seen : sequences) EXPECT_TRUE(expected.count(seen)) << seen;
}

// The 16-colour mode: SGR 30-37 and 90-97 (40-47, 100-107 behind), a face's
// shades step from its hue's normal entry to its bright one, and no entry
// is too close to the background.
std::string Sgr16(Rgb face, double intensity, Background background, bool behind = false) {
  const TermColour colour = CellColour(face, intensity, ColourMode::k16, background);
  EXPECT_EQ(colour.kind, TermColour::Kind::kIndexed);
  EXPECT_LT(colour.index, 16);
  std::string out;
  if (behind) {
    AppendBackgroundSgr(colour, out);
  } else {
    AppendForegroundSgr(colour, out);
  }
  return out;
}

TEST(CellColour, SixteenColoursAreAnsiSgrWithShadesAndHue) {
  const Rgb grey = kDefaultFaceColour, red{0.8F, 0.05F, 0.05F}, blue{0.1F, 0.2F, 0.8F};
  EXPECT_EQ(Sgr16(grey, 0.0, Background::kDark), "\x1b[90m");  // dark grey, never black
  EXPECT_EQ(Sgr16(grey, 1.0, Background::kDark), "\x1b[37m");
  EXPECT_EQ(Sgr16({1, 1, 1}, 1.0, Background::kDark), "\x1b[97m");
  EXPECT_EQ(Sgr16(red, 0.3, Background::kDark), "\x1b[31m");
  EXPECT_EQ(Sgr16(red, 1.0, Background::kDark), "\x1b[91m");
  EXPECT_EQ(Sgr16(blue, 0.0, Background::kDark), "\x1b[34m");
  EXPECT_EQ(Sgr16(blue, 1.0, Background::kDark), "\x1b[94m");
  EXPECT_EQ(Sgr16(blue, 1.0, Background::kDark, true), "\x1b[104m");
  EXPECT_EQ(Sgr16(red, 0.0, Background::kLight), "\x1b[30m");  // black on white
  EXPECT_EQ(Sgr16(red, 0.5, Background::kLight, true), "\x1b[41m");
  for (const Background background : {Background::kDark, Background::kLight}) {
    const Srgb8 back = background == Background::kDark ? Srgb8{0, 0, 0} : Srgb8{255, 255, 255};
    for (const Rgb face : {grey, red, blue, Rgb{1, 1, 0}, Rgb{0, 1, 1}, Rgb{1, 1, 1}}) {
      std::set<int> seen;
      for (int level = 0; level < 8; ++level) {
        const TermColour colour = CellColour(face, level / 7.0, ColourMode::k16, background);
        seen.insert(colour.index);
        EXPECT_GE(ContrastRatio(kXtermPalette16[colour.index], back), kMinBackgroundContrast);
      }
      if (background == Background::kDark) {
        EXPECT_GE(seen.size(), 2U);  // shading shows
      }
    }
  }
  // The ansi dump of a 16-colour frame has no 256-colour or 24-bit SGR.
  Scene scene = test::LoadScene("data/cube.dat");
  RenderOptions options;
  const test::Frame frame = test::RenderFrame(scene, 0.3, 1.3, 40, 16, options);
  std::string ansi;
  AppendAnsiFrame(frame.cells, {}, options.ramp.LevelCount(), ColourMode::k16, ansi);
  EXPECT_NE(ansi.find("\x1b[37m"), std::string::npos);
  EXPECT_EQ(ansi.find("38;"), std::string::npos);
}

}  // namespace
}  // namespace termshade
