// AnsiFrameDiff and the recordings made with it: a terminal that replays a
// render's asciicast shows, after every event, exactly the screen the
// frame drawn whole gives (glyphs and both colours of every cell), in every
// glyph mode and colour mode; and the changes are smaller than the frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/write/AnsiCells.h"
#include "io/write/AnsiFrameDiff.h"
#include "io/write/AsciicastRecording.h"
#include "shade/ColourMode.h"
#include "shade/Utf8.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

// A small terminal: CUP, CR, LF, SGR (kept per cell), ED 2, DECTCEM, and
// UTF-8 glyphs one cell each. Anything else, a glyph past the right edge
// (auto-wrap) or a line feed off the bottom (scrolling) fails the test:
// a recording must not depend on them.
class TerminalModel {
 public:
  TerminalModel(int widthCells, int heightCells)
      : width_(widthCells),
        height_(heightCells),
        cells_(static_cast<size_t>(widthCells) * heightCells) {}

  void Feed(std::string_view bytes) {
    size_t i = 0;
    while (i < bytes.size()) {
      const char c = bytes[i];
      if (c == '\x1b') {
        i = Escape(bytes, i);
      } else if (c == '\r') {
        col_ = 0;
        ++i;
      } else if (c == '\n') {
        if (++row_ >= height_) ADD_FAILURE() << "line feed off the bottom: the screen scrolls";
        ++i;
      } else {
        i = Glyph(bytes, i);
      }
    }
  }

  const std::vector<AnsiCell>& Cells() const { return cells_; }
  int Width() const { return width_; }

 private:
  // CSI [?] params final, from bytes[i] (the ESC); the index after it.
  size_t Escape(std::string_view bytes, size_t i) {
    if (i + 1 >= bytes.size() || bytes[i + 1] != '[') {
      ADD_FAILURE() << "escape that is not CSI at " << i;
      return bytes.size();
    }
    size_t end = i + 2;
    const bool privateMode = end < bytes.size() && bytes[end] == '?';
    if (privateMode) ++end;
    const size_t paramsStart = end;
    while (end < bytes.size() &&
           (std::isdigit(static_cast<unsigned char>(bytes[end])) != 0 || bytes[end] == ';')) {
      ++end;
    }
    if (end >= bytes.size()) {
      ADD_FAILURE() << "unfinished CSI";
      return bytes.size();
    }
    const std::vector<int> params = Params(bytes.substr(paramsStart, end - paramsStart));
    const char final = bytes[end];
    if (privateMode) {
      if (!(params == std::vector<int>{25} && (final == 'l' || final == 'h')))
        ADD_FAILURE() << "unknown private mode sequence";
    } else if (final == 'H') {
      row_ = params.empty() ? 0 : std::max(params[0], 1) - 1;
      col_ = params.size() < 2 ? 0 : std::max(params[1], 1) - 1;
      if (row_ >= height_ || col_ >= width_) ADD_FAILURE() << "cursor move off the screen";
    } else if (final == 'J' && params == std::vector<int>{2}) {
      for (AnsiCell& cell : cells_) cell = AnsiCell{U' ', {}, pen_.background};
    } else if (final == 'm') {
      Sgr(params);
    } else {
      ADD_FAILURE() << "unknown CSI final " << final;
    }
    return end + 1;
  }

  static std::vector<int> Params(std::string_view text) {
    std::vector<int> params;
    if (text.empty()) return params;
    int value = 0;
    for (const char c : text) {
      if (c == ';') {
        params.push_back(value);
        value = 0;
      } else {
        value = value * 10 + (c - '0');
      }
    }
    params.push_back(value);
    return params;
  }

  // One colour after 38 or 48: 5;n or 2;r;g;b; the index after it.
  static size_t Extended(const std::vector<int>& p, size_t i, TermColour& colour) {
    if (i + 1 < p.size() && p[i] == 5) {
      colour = test::IndexedColour(p[i + 1]);
      return i + 2;
    }
    if (i + 3 < p.size() && p[i] == 2) {
      colour = TermColour{};
      colour.kind = TermColour::Kind::kRgb;
      colour.rgb = {static_cast<uint8_t>(p[i + 1]), static_cast<uint8_t>(p[i + 2]),
                    static_cast<uint8_t>(p[i + 3])};
      return i + 4;
    }
    ADD_FAILURE() << "bad extended colour";
    return p.size();
  }

  void Sgr(std::vector<int> p) {
    if (p.empty()) p.push_back(0);
    for (size_t i = 0; i < p.size();) {
      const int n = p[i++];
      if (n == 0) {
        pen_ = AnsiCell{};
      } else if (n >= 30 && n <= 37) {
        pen_.foreground = test::IndexedColour(n - 30);
      } else if (n >= 90 && n <= 97) {
        pen_.foreground = test::IndexedColour(n - 90 + 8);
      } else if (n >= 40 && n <= 47) {
        pen_.background = test::IndexedColour(n - 40);
      } else if (n >= 100 && n <= 107) {
        pen_.background = test::IndexedColour(n - 100 + 8);
      } else if (n == 39) {
        pen_.foreground = {};
      } else if (n == 49) {
        pen_.background = {};
      } else if (n == 38) {
        i = Extended(p, i, pen_.foreground);
      } else if (n == 48) {
        i = Extended(p, i, pen_.background);
      } else {
        ADD_FAILURE() << "unknown SGR " << n;
      }
    }
  }

  // One UTF-8 code point from bytes[i], written at the cursor; the index after it.
  size_t Glyph(std::string_view bytes, size_t i) {
    const auto lead = static_cast<unsigned char>(bytes[i]);
    const size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
    const auto decoded = DecodeUtf8(bytes.substr(i, length));
    if (!decoded || decoded->size() != 1 || (*decoded)[0] < 0x20) {
      ADD_FAILURE() << "not one printable code point at " << i;
      return i + 1;
    }
    if (col_ >= width_) {
      ADD_FAILURE() << "glyph past the right edge of row " << row_ << ": auto-wrap";
      return i + length;
    }
    AnsiCell& cell = cells_[static_cast<size_t>(row_) * width_ + col_];
    cell = pen_;
    cell.glyph = (*decoded)[0];
    ++col_;
    return i + length;
  }

  int width_, height_;
  int col_ = 0, row_ = 0;
  AnsiCell pen_;  ///< the colours the next glyph takes (its glyph unused)
  std::vector<AnsiCell> cells_;
};

// Whether two cells of a screen look the same: glyph, background, and the
// foreground unless the glyph is a blank (which shows none).
bool LookAlike(const AnsiCell& a, const AnsiCell& b) {
  return a.glyph == b.glyph && a.background == b.background &&
         (a.glyph == U' ' || a.foreground == b.foreground);
}

// The first cell where two screens look different, or "".
std::string FirstDifference(const TerminalModel& a, const TerminalModel& b) {
  for (size_t i = 0; i < a.Cells().size(); ++i) {
    const AnsiCell& x = a.Cells()[i];
    const AnsiCell& y = b.Cells()[i];
    if (LookAlike(x, y)) continue;
    std::ostringstream text;
    text << "cell " << i % a.Width() << "," << i / a.Width() << ": U+" << std::hex
         << static_cast<uint32_t>(x.glyph) << " vs U+" << static_cast<uint32_t>(y.glyph) << std::dec
         << ", fg kinds " << static_cast<int>(x.foreground.kind) << "/"
         << static_cast<int>(y.foreground.kind) << ", bg kinds "
         << static_cast<int>(x.background.kind) << "/" << static_cast<int>(y.background.kind);
    return text.str();
  }
  return "";
}

// The screen a frame drawn whole gives: the full recording's first event.
TerminalModel WholeFrameScreen(const AnsiCells& frame) {
  AsciicastRecording whole(frame.WidthCells(), frame.HeightCells(), 1.0);
  std::string out;
  whole.AppendFrame(frame, out);
  std::istringstream lines(out);
  std::string header, event;
  std::getline(lines, header);
  std::getline(lines, event);
  TerminalModel screen(frame.WidthCells(), frame.HeightCells());
  screen.Feed(nlohmann::json::parse(event)[2].get<std::string>());
  return screen;
}

struct Case {
  GlyphMode glyphs;
  ColourMode colour;
  Background background = Background::kDark;
};

// The frames of a turntable of the scene in one glyph and colour mode, as
// `termshade render` makes them, with a frame repeated (no event for it).
std::vector<AnsiCells> Turntable(const Scene& scene, const Case& c, int widthCells,
                                 int heightCells) {
  RenderOptions options;
  options.glyphs = c.glyphs;
  options.twoColour = true;
  options.textures = c.colour != ColourMode::kNone;
  std::vector<AnsiCells> frames;
  for (int i = 0; i < 7; ++i) {
    const double theta = 0.3 + 0.21 * (i == 4 ? 3 : i);  // frame 4 repeats frame 3
    const test::Frame frame =
        test::RenderFrame(scene, theta, 1.2, widthCells, heightCells, options);
    frames.emplace_back();
    FillAnsiCells(frame.cells, scene.source.faceColors, options.ramp.LevelCount(), c.colour,
                  frames.back(), c.background);
  }
  return frames;
}

// Replays the recording of the frames; after each event (and at each frame
// time without one) the screen must be the frame drawn whole.
void ExpectReplayShowsEveryFrame(const std::vector<AnsiCells>& frames, const std::string& label) {
  const int width = frames[0].WidthCells(), height = frames[0].HeightCells();
  constexpr double kFps = 10.0;
  AsciicastRecording recording(width, height, kFps);
  std::string out;
  for (const AnsiCells& frame : frames) recording.AppendFrame(frame, out);
  std::istringstream lines(out);
  std::string line;
  std::getline(lines, line);  // the header
  std::vector<nlohmann::json> events;
  while (std::getline(lines, line)) events.push_back(nlohmann::json::parse(line));
  TerminalModel screen(width, height);
  size_t next = 0;
  size_t wholeBytes = 0, sentBytes = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    if (next < events.size() &&
        std::lround(events[next][0].get<double>() * kFps) == static_cast<long>(f)) {
      const std::string bytes = events[next++][2].get<std::string>();
      screen.Feed(bytes);
      sentBytes += bytes.size();
    } else {
      EXPECT_GT(f, 0U) << label << ": no event for the first frame";
    }
    const TerminalModel expected = WholeFrameScreen(frames[f]);
    EXPECT_EQ(FirstDifference(screen, expected), "") << label << ", frame " << f;
    std::string ansi;
    AppendAnsiRows(frames[f], ansi);
    wholeBytes += ansi.size();
  }
  EXPECT_EQ(next, events.size()) << label;
  EXPECT_EQ(events.size(), frames.size() - 1) << label << ": the repeated frame has no event";
  EXPECT_LT(sentBytes, wholeBytes) << label;
}

TEST(AnsiFrameDiff, ReplayGivesEachFramesScreenInEveryGlyphAndColourMode) {
  const Scene scene = test::LoadScene("data/sphere_cone.dat");
  const std::vector<Case> cases{
      {GlyphMode::kSextants, ColourMode::kTrueColour},
      {GlyphMode::kQuadrants, ColourMode::k256},
      {GlyphMode::kBraille, ColourMode::k16},
      {GlyphMode::kRamp, ColourMode::kNone},
      {GlyphMode::kBlocks, ColourMode::kTrueColour, Background::kLight},
      {GlyphMode::kAscii, ColourMode::k256},
      {GlyphMode::kRamp, ColourMode::k16},
      {GlyphMode::kSextants, ColourMode::kNone},
  };
  for (const Case& c : cases) {
    const std::string label =
        std::string(GlyphModeName(c.glyphs)) + " " + std::string(ColourModeName(c.colour));
    ExpectReplayShowsEveryFrame(Turntable(scene, c, 48, 18), label);
  }
}

// Hand-made frames: every colour kind next to one another, blanks that keep
// a colour, changes at the edges and runs with gaps of every length.
TEST(AnsiFrameDiff, ReplayGivesEachFramesScreenForMadeUpFrames) {
  const int width = 30, height = 4;
  std::vector<AnsiCells> frames(6);
  const std::u32string glyphs = U" .:#\u2588\u2598\u28ff\U0001FB0F";
  for (size_t f = 0; f < frames.size(); ++f) {
    AnsiCells& frame = frames[f];
    frame.Resize(width, height);
    for (int row = 0; row < height; ++row) {
      for (int col = 0; col < width; ++col) {
        // Cells change where (col * row + f) hits a pattern that thins out with f.
        const size_t k =
            static_cast<size_t>(col * 7 + row * 3) + (col % (static_cast<int>(f) + 2) == 0 ? f : 0);
        AnsiCell& cell = frame.At(col, row);
        cell.glyph = glyphs[k % glyphs.size()];
        switch (k % 5) {
          case 0:
            break;
          case 1:
            cell.foreground = test::IndexedColour(k % 16);
            break;
          case 2:
            cell.foreground = test::IndexedColour(16 + k % 200);
            break;
          case 3:
            cell.foreground.kind = TermColour::Kind::kRgb;
            cell.foreground.rgb = {static_cast<uint8_t>(k), 40, static_cast<uint8_t>(f)};
            break;
          default:
            cell.background = test::IndexedColour(k % 8);
            break;
        }
      }
    }
  }
  frames.insert(frames.begin() + 3, frames[2]);  // a repeated frame
  ExpectReplayShowsEveryFrame(frames, "made up");
}

TEST(AnsiFrameDiff, EqualFramesNothingOneCellAMoveAndShortGapsSentAgain) {
  AnsiCells before;
  before.Resize(12, 3);
  std::string out;
  AppendAnsiFrameDiff(before, before, out);
  EXPECT_EQ(out, "");
  AnsiCells after = before;
  after.At(2, 1).glyph = U'#';
  after.At(2, 1).foreground = test::IndexedColour(200);
  AppendAnsiFrameDiff(before, after, out);
  EXPECT_EQ(out, "\x1b[2;3H\x1b[38;5;200m#\x1b[0m");
  // Two unchanged cells between changes cost less than a move: sent again
  // (blanks, in whatever foreground the pen has).
  after.At(5, 1).glyph = U'%';
  out.clear();
  AppendAnsiFrameDiff(before, after, out);
  EXPECT_EQ(out, "\x1b[2;3H\x1b[38;5;200m#  \x1b[0m%");
  // A change on the last row's last cell, in the terminal's colours.
  after.At(11, 2).glyph = U'@';
  out.clear();
  AppendAnsiFrameDiff(before, after, out);
  EXPECT_EQ(out, "\x1b[2;3H\x1b[38;5;200m#  \x1b[0m%\x1b[3;12H@");
}

// A frame of glyph `glyph` in colour `index` everywhere.
AnsiCells FilledFrame(int width, int height, char32_t glyph, int index) {
  AnsiCells frame;
  frame.Resize(width, height);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col)
      frame.At(col, row) = {glyph, test::IndexedColour(index), {}};
  }
  return frame;
}

TEST(AnsiFrameDiff, AFrameOfAnotherSizeClearsTheScreenFirst) {
  const AnsiCells big = FilledFrame(30, 4, U'#', 3), small = FilledFrame(20, 3, U'.', 5);
  TerminalModel screen = WholeFrameScreen(big);
  std::string bytes;
  AppendAnsiFrameDiff(big, small, bytes);
  EXPECT_EQ(bytes.rfind("\x1b[2J", 0), 0U) << "the screen is cleared first";
  screen.Feed(bytes);
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 30; ++col) {
      const AnsiCell& cell = screen.Cells()[static_cast<size_t>(row) * 30 + col];
      const bool inside = col < 20 && row < 3;
      EXPECT_EQ(cell.glyph, inside ? U'.' : U' ') << col << "," << row;
    }
  }
}

TEST(AsciicastRecording, AFrameOfAnotherSizeLeavesNothingOfTheLast) {
  AsciicastRecording recording(30, 4, 1.0);
  std::string out;
  recording.AppendFrame(FilledFrame(30, 4, U'#', 3), out);
  recording.AppendFrame(FilledFrame(20, 3, U'#', 3), out);
  std::istringstream lines(out);
  std::string header, firstEvent, secondEvent;
  std::getline(lines, header);
  std::getline(lines, firstEvent);
  std::getline(lines, secondEvent);
  TerminalModel screen(30, 4);
  screen.Feed(nlohmann::json::parse(firstEvent)[2].get<std::string>());
  screen.Feed(nlohmann::json::parse(secondEvent)[2].get<std::string>());
  EXPECT_EQ(screen.Cells()[29].glyph, U' ') << "the first row's end is cleared";
  EXPECT_EQ(screen.Cells()[3 * 30].glyph, U' ') << "the last row is cleared";
  EXPECT_EQ(screen.Cells()[0].glyph, U'#');
}

}  // namespace
}  // namespace termshade
