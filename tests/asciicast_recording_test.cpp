// AsciicastRecording: a v2 header once, one event per frame at a steady
// rate, frames drawn from the top left without scrolling.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/write/AsciicastRecording.h"

namespace termshade {
namespace {

std::vector<nlohmann::json> Lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

TEST(AsciicastRecording, HeaderThenOneEventPerFrameAtTheRate) {
  AsciicastRecording recording(3, 2, 20.0);
  std::string out;
  recording.AppendFrame("ab\x1b[38;5;21mc\x1b[0m\nd\"\\\n", out);
  recording.AppendFrame("xyz\nuvw\n", out);
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
  EXPECT_EQ(lines[2][2], "\x1b[Hxyz\r\nuvw");
  EXPECT_EQ(lines[3][0], lines[2][0]);
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
