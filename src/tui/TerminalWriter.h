#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "tui/ScreenGrid.h"

namespace termshade {

/// Sends a ScreenGrid to the terminal: only the cells that changed since the
/// last frame, encoded with the terminal's own terminfo strings, in one
/// write(). (ncurses' doupdate() would do the diff too, but Debian's ncurses
/// 6.4 flushes at every cursor move: one write() per changed row.)
class TerminalWriter {
 public:
  explicit TerminalWriter(int outputFd) : outputFd_(outputFd) {}
  /// Appends to `sink` instead of writing (a recording of what the screen shows).
  explicit TerminalWriter(std::string* sink) : outputFd_(-1), sink_(sink) {}
  /// Leaves default attributes and a visible cursor behind (ncurses does not
  /// know what this writer set, so its endwin() would not undo it).
  ~TerminalWriter();
  TerminalWriter(const TerminalWriter&) = delete;
  TerminalWriter& operator=(const TerminalWriter&) = delete;

  /// Shows grid; cursor is (col, row) to show the cursor there, or nothing to
  /// hide it; trailer goes out after the frame in the same write (FramePacer's request).
  void Present(const ScreenGrid& grid, std::optional<std::pair<int, int>> cursor,
               std::string_view trailer = {});
  /// Sends bytes as they are, in one write.
  void Send(std::string_view bytes);
  /// False when writing the bottom-right cell would scroll the screen
  /// (automatic margins without deferred wrap): Present leaves it alone.
  static bool BottomRightWritable();
  /// The next Present repaints every cell (after a resize, say) and hides the
  /// cursor again.
  void Invalidate() {
    valid_ = false;
    cursorShown_ = true;
  }
  /// Default attributes and a visible cursor, now (before the shell gets the
  /// terminal back for a while).
  void Release();
  size_t LastFrameBytes() const { return lastFrameBytes_; }
  /// The bytes that give the terminal back as a shell expects it, whatever
  /// state the viewer left: mouse reports off, default attributes, cursor
  /// shown, keypad local, alternate screen left (needs the terminfo entry).
  static std::string ResetSequence();

 private:
  /// Terminal attributes as SGR state: the least that changes them is sent.
  struct Attributes {
    bool reverse = false;
    TermColour foreground;
    TermColour background;
    bool operator==(const Attributes&) const = default;
  };
  static Attributes AttributesFor(const ScreenCell& cell);
  void AppendAttributes(const Attributes& wanted);
  void AppendMove(int col, int row);
  void WriteAll();

  int outputFd_;
  std::string* sink_ = nullptr;
  ScreenGrid previous_;
  bool valid_ = false;
  bool cursorShown_ = true;
  Attributes current_;
  std::string out_;
  size_t lastFrameBytes_ = 0;
};

}  // namespace termshade
