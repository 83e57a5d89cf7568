// The one key table against what the viewer binds, the `?` overlay,
// `termshade --help` and the man page.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <set>
#include <string>

#include "tui/ScreenGrid.h"
#include "tui/ScreenPainter.h"
#include "tui/ViewerAction.h"
#include "tui/ViewerKeys.h"

namespace termshade {
namespace {

std::string OutputOf(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  EXPECT_TRUE(pipe != nullptr) << command;
  std::string output;
  std::array<char, 4096> buffer{};
  while (pipe != nullptr) {
    const size_t read = std::fread(buffer.data(), 1, buffer.size(), pipe.get());
    if (read == 0) break;
    output.append(buffer.data(), read);
  }
  return output;
}

std::string GridText(const ScreenGrid& grid) {
  std::string text;
  for (int row = 0; row < grid.HeightCells(); ++row) {
    for (int col = 0; col < grid.WidthCells(); ++col) {
      text += static_cast<char>(grid.At(col, row).glyph);
    }
    text += '\n';
  }
  return text;
}

TEST(ViewerKeys, EveryBoundCharacterIsInTheTable) {
  std::set<char> documented;
  for (const ViewerKey& key : ViewerKeyTable())
    documented.insert(key.chars.begin(), key.chars.end());
  for (int c = 32; c < 127; ++c) {
    if (ActionForChar(c) != ViewerAction::kNone) {
      EXPECT_TRUE(documented.count(static_cast<char>(c)) == 1)
          << "'" << static_cast<char>(c)
          << "' does something in the viewer but is not in the key table";
    }
  }
}

TEST(ViewerKeys, EveryCharacterInTheTableIsBound) {
  for (const ViewerKey& key : ViewerKeyTable()) {
    for (const char c : key.chars) {
      EXPECT_NE(ActionForChar(c), ViewerAction::kNone) << "'" << c << "' in row " << key.keys;
    }
  }
}

TEST(ViewerKeys, OverlayShowsEveryRowWithinEightyColumns) {
  ScreenGrid grid;
  grid.Resize(80, 30);
  ScreenPainter().PaintHelp(grid);
  const std::string text = GridText(grid);
  for (const ViewerKey& key : ViewerKeyTable()) {
    EXPECT_NE(text.find(std::string(key.does)), std::string::npos) << key.does << "\n" << text;
    EXPECT_NE(text.find(std::string(key.keys)), std::string::npos) << key.keys << "\n" << text;
  }
}

// A short window shows the rows that fit and says where the rest are and how to close.
TEST(ViewerKeys, OverlayInAShortWindowSaysHowToClose) {
  for (const int rows : {3, 6, 12}) {
    ScreenGrid grid;
    grid.Resize(60, rows);
    ScreenPainter().PaintHelp(grid);
    const std::string text = GridText(grid);
    EXPECT_NE(text.find("more: termshade --help; any key closes this"), std::string::npos) << text;
  }
}

TEST(ViewerKeys, HelpListsTheTableAsFormatted) {
  const std::string help = OutputOf(std::string(TERMSHADE_EXECUTABLE) + " --help");
  ASSERT_NE(help.find("Keys in the viewer"), std::string::npos) << help;
  // Every row, keys then what they do, on one line of --help.
  for (const ViewerKey& key : ViewerKeyTable()) {
    bool found = false;
    size_t start = 0;
    for (size_t end = help.find('\n'); end != std::string::npos;
         start = end + 1, end = help.find('\n', start)) {
      const std::string line = help.substr(start, end - start);
      const size_t keysAt = line.find(std::string(key.keys));
      const size_t doesAt = line.find(std::string(key.does));
      if (keysAt == 2 && doesAt != std::string::npos && doesAt > keysAt) found = true;
    }
    EXPECT_TRUE(found) << "--help lacks the row '" << key.keys << "  " << key.does << "'\n" << help;
  }
  EXPECT_NE(help.find(FormatViewerKeys("  ")), std::string::npos) << help;
}

TEST(ViewerKeys, ManPageListsEveryRow) {
  const std::string man = OutputOf(std::string(TERMSHADE_EXECUTABLE) + " --generate man");
  const size_t keys = man.find(".SH KEYS"), next = man.find(".SH", keys + 1);
  ASSERT_NE(keys, std::string::npos) << man;
  const std::string section = man.substr(keys, next - keys);
  const auto roff = [](std::string_view text) {
    std::string escaped;
    for (const char c : text) escaped += c == '-' ? std::string("\\-") : std::string(1, c);
    return escaped;
  };
  for (const ViewerKey& key : ViewerKeyTable()) {
    EXPECT_NE(section.find(".TP\n\\fB" + roff(key.keys) + "\\fR\n" + roff(key.does) + "\n"),
              std::string::npos)
        << key.keys << "\n"
        << section;
  }
}

}  // namespace
}  // namespace termshade
