#pragma once

#include <optional>
#include <string>

#include "tui/TerminalWriter.h"

namespace termshade {

/// Why the viewer cannot take over the terminal, if it cannot.
std::optional<std::string> TerminalProblem();

/// The ncurses session, RAII: the constructor takes over the terminal
/// (cbreak, no echo, keypad, mouse, colour where there is some), the
/// destructor gives it back exactly once, whatever path leads there. ncurses
/// reads and decodes input and knows the terminal; drawing goes through
/// TerminalWriter.
/// SIGINT, SIGTERM, SIGHUP and SIGQUIT are turned into a byte on a pipe that
/// the event loop polls, so they end the loop and the destructor runs;
/// SIGTSTP (Ctrl-Z) and SIGCONT reach the loop the same way.
class TerminalSession {
 public:
  TerminalSession();
  ~TerminalSession();
  TerminalSession(const TerminalSession&) = delete;
  TerminalSession& operator=(const TerminalSession&) = delete;

  bool Ok() const { return screen_ != nullptr && inputPad_ != nullptr; }
  /// Colours available (fixed xterm indices; no palette is ever redefined).
  ColourSupport Colours() const { return colours_; }
  /// The next key (ncurses key codes, KEY_RESIZE and KEY_MOUSE included), or
  /// ERR when none is waiting. Read through a pad, so ncurses never draws.
  int NextKey();
  static int WidthCells();
  static int HeightCells();
  /// The read end of the signal pipe: readable once a handled signal arrived.
  int SignalFd() const { return signalPipe_[0]; }
  /// The signals that arrived since the last call (drains the pipe).
  struct Signals {
    bool terminate = false;  ///< SIGINT, SIGTERM, SIGHUP or SIGQUIT
    bool suspend = false;    ///< SIGTSTP: the user asked to stop (Ctrl-Z)
    bool resumed = false;    ///< SIGCONT: the screen may have been drawn over
  };
  Signals TakeSignals();
  /// Gives the terminal back, stops the process as SIGTSTP would, and takes
  /// the terminal again once continued (fg). The screen must then be redrawn.
  void Suspend();
  /// Cell height / width from the terminal's pixel size (TIOCGWINSZ), or 0.
  static double ReportedCellAspect();

 private:
  void InstallSignalHandlers();
  void RestoreSignalHandlers();

  void* screen_ = nullptr;    // SCREEN*, kept opaque so no header outside src/tui sees ncurses
  void* inputPad_ = nullptr;  // WINDOW*
  ColourSupport colours_ = ColourSupport::kNone;
  int signalPipe_[2] = {-1, -1};
};

}  // namespace termshade
