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
/// the event loop polls, so they end the loop and the destructor runs (the
/// caller then re-raises the signal: ReRaise); SIGTSTP (Ctrl-Z) and SIGCONT
/// reach the loop the same way. Every other signal whose default action ends
/// the process (SIGSEGV, SIGABRT, SIGUSR1, SIGALRM, SIGPIPE...) restores the
/// terminal inside its handler, async-signal-safely (a reset sequence made in
/// advance, the saved termios), then takes its default action, so the exit
/// status still says 128 + N.
class TerminalSession {
 public:
  TerminalSession();
  ~TerminalSession();
  TerminalSession(const TerminalSession&) = delete;
  TerminalSession& operator=(const TerminalSession&) = delete;

  bool Ok() const { return screen_ != nullptr && inputPad_ != nullptr; }
  /// The next key (ncurses key codes, KEY_RESIZE and KEY_MOUSE included), or
  /// ERR when none is waiting. Read through a pad, so ncurses never draws.
  int NextKey();
  /// NextKey, waiting up to `milliseconds` for one.
  int NextKeyWithin(int milliseconds);
  /// Bytes written to the terminal and not yet taken by the other end
  /// (TIOCOUTQ: a terminal emulator, or sshd, still to read them); 0 if unknown.
  static int OutputQueuedBytes();
  static int WidthCells();
  static int HeightCells();
  /// The read end of the signal pipe: readable once a handled signal arrived.
  int SignalFd() const { return signalPipe_[0]; }
  /// The signals that arrived since the last call (drains the pipe).
  struct Signals {
    int terminate = 0;     ///< SIGINT, SIGTERM, SIGHUP or SIGQUIT: its number, else 0
    bool suspend = false;  ///< SIGTSTP: the user asked to stop (Ctrl-Z)
    bool resumed = false;  ///< SIGCONT: the screen may have been drawn over
  };
  Signals TakeSignals();
  /// Gives the terminal back, stops the process as SIGTSTP would, and takes
  /// the terminal again once continued (fg). The screen must then be redrawn.
  void Suspend();
  /// Cell height / width from the terminal's pixel size (TIOCGWINSZ), or 0.
  static double ReportedCellAspect();
  /// Ends the process by signalNumber's default action (exit status 128 + N);
  /// call once the session is gone. Returns 128 + N if the signal did not end it.
  static int ReRaise(int signalNumber);

 private:
  void InstallSignalHandlers();
  void RestoreSignalHandlers();
  static void InstallFatalHandlers();
  static void RestoreFatalHandlers();

  void* screen_ = nullptr;    // SCREEN*, kept opaque so no header outside src/tui sees ncurses
  void* inputPad_ = nullptr;  // WINDOW*
  bool fatalHandlersInstalled_ = false;
  int signalPipe_[2] = {-1, -1};
};

}  // namespace termshade
