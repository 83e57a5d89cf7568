// AsciicastRecording: a v2 header once, one event per frame at a steady
// rate, the first frame drawn whole from the top left without scrolling,
// later ones only where they changed.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/write/AsciicastRecording.h"
#include "shade/Utf8.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

std::vector<nlohmann::json> Lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// Rows of code points (one a cell) in the terminal's colours.
AnsiCells Cells(const std::vector<std::string>& rows) {
  AnsiCells cells;
  cells.Resize(static_cast<int>(DecodeUtf8(rows[0])->size()), static_cast<int>(rows.size()));
  for (int row = 0; row < cells.HeightCells(); ++row) {
    const std::vector<char32_t> glyphs = *DecodeUtf8(rows[static_cast<size_t>(row)]);
    for (int col = 0; col < cells.WidthCells(); ++col) {
      cells.At(col, row).glyph = glyphs[static_cast<size_t>(col)];
    }
  }
  return cells;
}

TEST(AsciicastRecording, HeaderThenOneEventPerFrameAtTheRate) {
  AsciicastRecording recording(3, 2, 20.0);
  std::string out;
  AnsiCells first = Cells({"abc", "d\"\\"});
  first.At(2, 0).foreground = test::IndexedColour(21);
  recording.AppendFrame(first, out);
  recording.AppendFrame(Cells({"xyz", "uvw"}), out);
  recording.AppendEnd(out);
  const auto lines = Lines(out);
  ASSERT_EQ(lines.size(), 4U);
  EXPECT_EQ(lines[0]["version"], 2);
  EXPECT_EQ(lines[0]["width"], 3);
  EXPECT_EQ(lines[0]["height"], 2);
  EXPECT_EQ(lines[0]["theme"]["bg"], "#000000");
  EXPECT_FALSE(lines[0].contains("timestamp"));  // the same frames, the same bytes
  EXPECT_EQ(lines[1][0].get<double>(), 0.0);
  EXPECT_EQ(lines[1][1], "o");
  // The first frame hides the cursor and clears; rows joined by CR LF, none after the last.
  EXPECT_EQ(lines[1][2], "\x1b[?25l\x1b[2J\x1b[Hab\x1b[38;5;21mc\x1b[0m\r\nd\"\\");
  EXPECT_DOUBLE_EQ(lines[2][0].get<double>(), 0.05);
  // Every cell changed: the whole frame is shorter than moves to the two rows.
  EXPECT_EQ(lines[2][2], "\x1b[Hxyz\r\nuvw");
  EXPECT_EQ(lines[3][0], lines[2][0]);
  EXPECT_EQ(lines[3][2], "\x1b[?25h");
}

TEST(AsciicastRecording, LaterFramesSendOnlyWhatChangedAndUnchangedOnesNothing) {
  AsciicastRecording recording(20, 3, 10.0);
  std::string out;
  const AnsiCells first =
      Cells({"....................", "....................", "...................."});
  AnsiCells second = first;
  second.At(4, 1).glyph = U'\u2588';
  second.At(4, 1).foreground = test::IndexedColour(9);
  recording.AppendFrame(first, out);
  recording.AppendFrame(second, out);
  recording.AppendFrame(second, out);  // unchanged: no event
  recording.AppendEnd(out);
  const auto lines = Lines(out);
  ASSERT_EQ(lines.size(), 4U);
  EXPECT_DOUBLE_EQ(lines[2][0].get<double>(), 0.1);
  EXPECT_EQ(lines[2][2], "\x1b[2;5H\x1b[91m\u2588\x1b[0m");
  EXPECT_DOUBLE_EQ(lines[3][0].get<double>(), 0.2);  // the close keeps the last frame's time
  EXPECT_EQ(lines[3][2], "\x1b[?25h");
}

TEST(AsciicastRecording, NoFramesNoEvents) {
  AsciicastRecording recording(80, 24, 25.0);
  std::string out;
  recording.AppendEnd(out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace termshade
