#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include "io/write/OutputFile.h"
#include "shade/TerminalTheme.h"
#include "tui/ScreenGrid.h"
#include "tui/TerminalWriter.h"

namespace termshade {

/// `termshade MODEL --record FILE.cast`: what the viewer shows, as an
/// asciinema v2 recording. A header with the terminal's size at the first
/// frame and the theme of its background (as the terminal's answer said:
/// the header and the events after it are held until SettleTheme, at most
/// kMaxHeldBytes of them), then one output event per frame the viewer presents,
/// at the wall-clock time since the recording began: the whole screen
/// (frame and status line), redrawn from the screen grid as TerminalWriter
/// draws it (only what changed since the last frame), always in the frame's
/// full colours (never a cheaper frame sent while moving over a slow link),
/// and an "r" event when the terminal is resized. Written through
/// OutputFile: the file appears whole at Finish, or not at all.
class ViewerRecording {
 public:
  using Clock = std::chrono::steady_clock;

  explicit ViewerRecording(std::string path) : file_(std::move(path)) {}

  /// Creates the file; the message (without the path) if it cannot be.
  /// `theme`: the header's, unless SettleTheme gives another.
  std::optional<std::string> Open(const TerminalTheme& theme);
  /// The header's theme, known now (the terminal's start-up answers read):
  /// the header and the events held for it are written.
  void SettleTheme(const TerminalTheme& theme);
  /// One frame as the screen shows it at `now`; cursor as TerminalWriter::Present takes it.
  void Frame(const ScreenGrid& grid, std::optional<std::pair<int, int>> cursor,
             Clock::time_point now);
  /// The closing event (cursor shown, attributes reset), then the file in
  /// place; the first error met while recording, if any.
  std::optional<std::string> Finish(Clock::time_point now);

 private:
  void AppendEvent(double seconds, char type, std::string_view text);
  std::string Header() const;
  void Flush();

  OutputFile file_;
  TerminalTheme theme_;
  std::string pending_;  ///< file bytes not yet written
  std::string bytes_;    ///< the writer's output for the frame being recorded
  TerminalWriter writer_{&bytes_};
  std::optional<Clock::time_point> start_;
  int widthCells_ = 0;
  int heightCells_ = 0;
  int headerWidthCells_ = 0;  ///< the size at the first frame
  int headerHeightCells_ = 0;
  bool themeSettled_ = false;
  bool headerWritten_ = false;
  std::optional<std::string> error_;
};

}  // namespace termshade
