// ViewerRecording (--record): the header's theme is the one settled once
// the terminal's start-up answers are read, not the guess made before them;
// the events held for it are bounded.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/TestSupport.h"
#include "tui/ViewerRecording.h"

namespace termshade {
namespace {

using Clock = ViewerRecording::Clock;

std::vector<nlohmann::json> Lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// A screen of `letter`s: every frame after one of another letter changes every cell.
ScreenGrid Screen(int width, int height, char letter) {
  ScreenGrid grid;
  grid.Resize(width, height);
  for (int row = 0; row < height; ++row) {
    grid.Put(0, row, std::string(static_cast<size_t>(width), letter), CellStyle::kPlain);
  }
  return grid;
}

TEST(ViewerRecording, TheHeaderTakesTheThemeSettledAfterTheFirstFrames) {
  test::ScratchFolder folder("viewer_recording_settled");
  const std::string path = folder.Write("light.cast", "");
  ViewerRecording recording(path);
  ASSERT_FALSE(recording.Open(ThemeFor(Background::kDark)));  // the guess
  const Clock::time_point start{};
  recording.Frame(Screen(20, 4, 'a'), std::nullopt, start);
  recording.Frame(Screen(20, 4, 'b'), std::nullopt, start + std::chrono::milliseconds(300));
  recording.SettleTheme(ThemeFor(Background::kLight));  // the terminal answered light
  recording.Frame(Screen(20, 4, 'c'), std::nullopt, start + std::chrono::milliseconds(600));
  ASSERT_FALSE(recording.Finish(start + std::chrono::seconds(1)));
  const auto lines = Lines(test::ReadFile(path));
  ASSERT_EQ(lines.size(), 5U);  // the header, three frames, the end
  EXPECT_EQ(lines[0]["width"], 20);
  EXPECT_EQ(lines[0]["height"], 4);
  EXPECT_EQ(lines[0]["theme"]["bg"], "#ffffff");
  EXPECT_EQ(lines[0]["theme"]["fg"], "#000000");
  EXPECT_EQ(lines[1][0].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(lines[2][0].get<double>(), 0.3);
}

TEST(ViewerRecording, EventsHeldForTheThemeAreBounded) {
  test::ScratchFolder folder("viewer_recording_bounded");
  const std::string path = folder.Write("held.cast", "");
  ViewerRecording recording(path);
  ASSERT_FALSE(recording.Open(ThemeFor(Background::kDark)));
  // Over 4 MiB of frames (200 x 50, every cell changed) and no theme settled:
  // the header goes out with the guess, and a theme settled later is too late.
  const Clock::time_point start{};
  for (int i = 0; i < 500; ++i) {
    recording.Frame(Screen(200, 50, i % 2 == 0 ? 'a' : 'b'), std::nullopt,
                    start + std::chrono::milliseconds(i));
  }
  recording.SettleTheme(ThemeFor(Background::kLight));
  ASSERT_FALSE(recording.Finish(start + std::chrono::seconds(1)));
  const auto lines = Lines(test::ReadFile(path));
  ASSERT_EQ(lines.size(), 502U);
  EXPECT_EQ(lines[0]["theme"]["bg"], "#000000");
}

}  // namespace
}  // namespace termshade
