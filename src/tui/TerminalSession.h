#pragma once

#include <optional>
#include <string>

namespace termshade {

/// Why the viewer cannot take over the terminal, if it cannot.
std::optional<std::string> TerminalProblem();

/// The ncurses session, RAII: the constructor takes over the terminal
/// (cbreak, no echo, keypad, mouse, colour where there is some), the
/// destructor gives it back exactly once, whatever path leads there.
/// SIGINT, SIGTERM, SIGHUP and SIGQUIT are turned into a byte on a pipe that
/// the event loop polls, so they end the loop and the destructor runs.
class TerminalSession {
 public:
  TerminalSession();
  ~TerminalSession();
  TerminalSession(const TerminalSession&) = delete;
  TerminalSession& operator=(const TerminalSession&) = delete;

  bool Ok() const { return screen_ != nullptr; }
  /// 256 colours available (fixed xterm indices; no palette is redefined).
  bool Has256Colours() const { return colours256_; }
  bool HasColours() const { return colours_; }
  /// The read end of the signal pipe: readable once a terminating signal arrived.
  int SignalFd() const { return signalPipe_[0]; }
  /// True once a terminating signal arrived (drains the pipe).
  bool TakeSignal();
  /// Cell height / width from the terminal's pixel size (TIOCGWINSZ), or 0.
  static double ReportedCellAspect();

 private:
  void InstallSignalHandlers();
  void RestoreSignalHandlers();

  void* screen_ = nullptr;  // SCREEN*, kept opaque so no header outside src/tui sees ncurses
  bool colours_ = false;
  bool colours256_ = false;
  int signalPipe_[2] = {-1, -1};
};

}  // namespace termshade
