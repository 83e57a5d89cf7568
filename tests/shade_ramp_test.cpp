// Shade ramps: UTF-8 in, one glyph per level out, the same picture whatever
// the characters.
#include <gtest/gtest.h>

#include "raster/Renderer.h"
#include "shade/ShadeRamp.h"
#include "shade/Utf8.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

TEST(Utf8, DecodesAndEncodesEveryLength) {
  const std::string text =
      "a\xC3\xA9\xE2\x96\x91\xF0\x9F\x99\x82";  // a, e-acute, light shade, emoji
  const auto codePoints = DecodeUtf8(text);
  ASSERT_TRUE(codePoints.has_value());
  EXPECT_EQ(*codePoints, (std::vector<char32_t>{U'a', 0xE9, 0x2591, 0x1F642}));
  std::string again;
  for (char32_t c : *codePoints) AppendUtf8(again, c);
  EXPECT_EQ(again, text);
}

TEST(Utf8, RejectsWhatIsNotUtf8) {
  for (const std::string bad : {"\xFF", "\xC3", "\xC0\xAF", "\xE0\x80\xAF", "\xED\xA0\x80",
                                "\xF4\x90\x80\x80", "a\x80", "\xE2\x96"}) {
    EXPECT_FALSE(DecodeUtf8(bad).has_value()) << testing::PrintToString(bad);
  }
}

TEST(ShadeRamp, TakesOneCellGlyphsAndSaysWhyNot) {
  EXPECT_FALSE(ShadeRamp::Problem("\xE2\x96\x91\xE2\x96\x92\xE2\x96\x93\xE2\x96\x88"));  // blocks
  EXPECT_FALSE(ShadeRamp::Problem("\xE2\xA0\x81\xE2\xA3\xBF"));                          // braille
  EXPECT_EQ(ShadeRamp("\xE2\x96\x91\xE2\x96\x88").LevelCount(), 2);
  EXPECT_EQ(ShadeRamp("\xE2\x96\x91\xE2\x96\x88").Glyph(1), char32_t{0x2588});
  EXPECT_FALSE(ShadeRamp("\xE2\x96\x91").IsAscii());
  EXPECT_TRUE(ShadeRamp().IsAscii());
  EXPECT_EQ(ShadeRamp::Problem(""), "the ramp needs at least one character");
  EXPECT_EQ(ShadeRamp::Problem("\xFF"), "the ramp is not valid UTF-8");
  EXPECT_EQ(ShadeRamp::Problem(".: "),
            "the ramp may not contain a blank (the background is blank)");
  EXPECT_EQ(ShadeRamp::Problem("\xE2\xA0\x80").value_or("").substr(0, 6),
            "U+2800");  // blank braille
  EXPECT_EQ(ShadeRamp::Problem("\xE6\xBC\xA2").value_or("").substr(0, 6),
            "U+6F22");  // two cells wide
  EXPECT_EQ(ShadeRamp::Problem("\x1B").value_or("").substr(0, 6), "U+001B");
  EXPECT_EQ(ShadeRamp::Problem("\xCC\x81").value_or("").substr(0, 6), "U+0301");  // combining
  EXPECT_EQ(ShadeRamp::Problem(std::string(65, '#')), "the ramp has more than 64 characters");
}

TEST(ShadeRamp, BlockGlyphsDrawTheSamePictureAsLetters) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  RenderOptions letters, blocks;
  letters.ramp = ShadeRamp("abcd");
  blocks.ramp = ShadeRamp("\xE2\x96\x91\xE2\x96\x92\xE2\x96\x93\xE2\x96\x88");
  const test::Frame expected = test::RenderFrame(scene, 1.9, 1.15, 64, 20, letters);
  const test::Frame actual = test::RenderFrame(scene, 1.9, 1.15, 64, 20, blocks);
  const std::u32string from = U"abcd", to = U"\u2591\u2592\u2593\u2588";
  int drawn = 0;
  for (size_t i = 0; i < expected.cells.Glyphs().size(); ++i) {
    const char32_t letter = expected.cells.Glyphs()[i];
    const size_t level = from.find(letter);
    const char32_t wanted = level == std::u32string::npos ? letter : to[level];
    EXPECT_EQ(actual.cells.Glyphs()[i], wanted) << i;
    drawn += level == std::u32string::npos ? 0 : 1;
  }
  EXPECT_GT(drawn, 100);
  for (int row = 0; row < 20; ++row) {
    EXPECT_EQ(DecodeUtf8(actual.cells.RowText(row)).value_or(std::vector<char32_t>{}).size(), 64U);
  }
}

}  // namespace
}  // namespace termshade
