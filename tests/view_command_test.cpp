#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tui/ClipboardSequence.h"
#include "tui/ShellQuote.h"
#include "tui/ViewCommand.h"

namespace termshade {
namespace {

TEST(ShellQuote, PlainWordsStayQuotedOnesComeBackWhole) {
  EXPECT_EQ(ShellQuote("/models/duck.dae"), "/models/duck.dae");
  EXPECT_EQ(ShellQuote("my duck.dae"), "'my duck.dae'");
  EXPECT_EQ(ShellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(ShellQuote(""), "''");
  EXPECT_EQ(ShellQuote("$(rm -rf ~)"), "'$(rm -rf ~)'");
  EXPECT_EQ(ShellQuote("caf\xc3\xa9"), "'caf\xc3\xa9'");
  // Control bytes and invalid UTF-8 never go out as themselves.
  EXPECT_EQ(ShellQuote("a\nb"), "$'a\\x0ab'");
  EXPECT_EQ(ShellQuote("\x1b]0;x\a'"), "$'\\x1b]0;x\\x07\\x27'");
  EXPECT_EQ(ShellQuote("\xff"), "$'\\xff'");
}

TEST(ShellQuote, BashReadsItBack) {
  for (const std::string word : {"plain", "two words", "it's", "a\nb", "\x1b[31m", "\xfe\xff"}) {
    std::string expected;
    for (const unsigned char c : word) {
      char hex[8];
      std::snprintf(hex, sizeof hex, " %02x", c);
      expected += hex;
    }
    const std::string script = "printf %s " + ShellQuote(word) + " | od -An -tx1 -v";
    FILE* pipe = popen(("bash -c " + ShellQuote(script)).c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
    pclose(pipe);
    std::string compact;
    for (const char c : output) {
      if (c != '\n') compact += c;
    }
    EXPECT_EQ(compact, expected) << word;
  }
}

TEST(ClipboardSequence, Osc52WithBase64) {
  EXPECT_EQ(Base64(""), "");
  EXPECT_EQ(Base64("f"), "Zg==");
  EXPECT_EQ(Base64("fo"), "Zm8=");
  EXPECT_EQ(Base64("foo"), "Zm9v");
  EXPECT_EQ(Base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(Base64("\xff\xfe"), "//4=");
  EXPECT_EQ(ClipboardSequence("hi"), "\x1b]52;c;aGk=\a");
}

TEST(ViewCommand, NumbersReadBackExactly) {
  for (const double value : {0.3, 0.30000000000000004, 2.3000000000000003, -0.7, 1e-300,
                             4.5678901234567891, std::nextafter(1.3, 2.0), 9.8488578017961039}) {
    const std::string text = ExactNumber(value);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    EXPECT_EQ(static_cast<double>(std::strtold(text.c_str(), nullptr)), value) << text;
  }
  EXPECT_EQ(ExactNumber(0.3), "0.3");
}

TEST(ViewCommand, EveryOptionOfTheView) {
  ViewToReproduce shown;
  shown.modelPath = "/m/my duck.dae";
  shown.widthCells = 160;
  shown.heightCells = 47;
  shown.view = {4.5, -0.25, 1.25};
  shown.upAxis = UpAxis::kMinusY;
  shown.render.glyphs = GlyphMode::kSextants;
  shown.render.method = Method::kPainter;
  shown.render.shade = ShadeMode::kLambert;
  shown.render.cullBackFaces = false;
  shown.colour = ColourMode::kTrueColour;
  shown.sunAzimuthRadians = -0.2;
  shown.sunElevationRadians = 0.1;
  EXPECT_EQ(
      RenderCommandFor(shown),
      "termshade render '/m/my duck.dae' --size 160x47 --theta=-0.25 --phi 1.25 --rho 4.5 "
      "--fit --up=-y --cell-aspect 2 --method painter --shade lambert --glyphs sextants --no-cull "
      "--light=-0.2,0.1 --color truecolor --background dark --format ansi");
  shown.colour = ColourMode::kNone;
  shown.render = RenderOptions{};
  shown.render.ramp = ShadeRamp(".oO#");
  shown.sunAzimuthRadians = shown.sunElevationRadians = 0.0;
  shown.levelOfDetail = true;
  shown.fitRho = 2.25;  // after f
  EXPECT_EQ(RenderCommandFor(shown),
            "termshade render '/m/my duck.dae' --size 160x47 --theta=-0.25 --phi 1.25 --rho 4.5 "
            "--fit --fit-rho 2.25 --up=-y --cell-aspect 2 --method zbuffer --shade contrast "
            "--glyphs ramp --ramp '.oO#' --lod auto --color none --background dark");
}

}  // namespace
}  // namespace termshade
