#include "tui/TerminalSession.h"

#include <curses.h>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <term.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace termshade {
namespace {

// The one piece of state a signal handler may touch: the pipe's write end.
// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables)
std::atomic<int> gSignalWriteFd{-1};

constexpr int kHandledSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGTSTP, SIGCONT};

// Signals whose default action ends the process and that a handler can
// catch, apart from those the event loop handles (SIGKILL and SIGSTOP
// cannot be caught). Real-time signals are added at run time.
constexpr int kFatalSignals[] = {SIGSEGV, SIGABRT, SIGBUS,  SIGFPE,  SIGILL,    SIGTRAP,
                                 SIGSYS,  SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF,
                                 SIGXCPU, SIGXFSZ, SIGPIPE, SIGPOLL, SIGPWR,    SIGSTKFLT};

// What a fatal-signal handler needs to give the terminal back, prepared
// while the session starts: the bytes to write and the termios to set.
struct FatalRestore {
  char reset[512];
  size_t resetBytes = 0;
  termios savedModes;
  bool modesSaved = false;
  std::atomic<bool> armed{false};  ///< the session holds the terminal now
};
// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables)
FatalRestore gFatalRestore;
// A stack of its own, so a stack overflow's SIGSEGV can still run the handler.
// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables)
alignas(16) char gAlternateStack[64 * 1024];

extern "C" void OnHandledSignal(int signalNumber) {
  const int fd = gSignalWriteFd.load();
  if (fd >= 0) {
    const auto byte = static_cast<char>(signalNumber);
    [[maybe_unused]] const ssize_t written = write(fd, &byte, 1);
  }
}

// Async-signal-safe only: write, tcsetattr, sigaction, sigprocmask, raise.
extern "C" void OnFatalSignal(int signalNumber) {
  if (gFatalRestore.armed.exchange(false)) {
    const char* bytes = gFatalRestore.reset;
    size_t left = gFatalRestore.resetBytes;
    while (left > 0) {
      const ssize_t n = write(STDOUT_FILENO, bytes, left);
      if (n <= 0) break;
      bytes += n;
      left -= static_cast<size_t>(n);
    }
    if (gFatalRestore.modesSaved) tcsetattr(STDIN_FILENO, TCSANOW, &gFatalRestore.savedModes);
  }
  // The default action, with the signal unblocked: the exit status says 128 + N.
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  sigaction(signalNumber, &fallback, nullptr);
  sigset_t unblock;
  sigemptyset(&unblock);
  sigaddset(&unblock, signalNumber);
  sigprocmask(SIG_UNBLOCK, &unblock, nullptr);
  raise(signalNumber);
}

template <typename PerSignal>
void ForEachFatalSignal(PerSignal perSignal) {
  for (int signalNumber : kFatalSignals) perSignal(signalNumber);
  for (int signalNumber = SIGRTMIN; signalNumber <= SIGRTMAX; ++signalNumber) {
    perSignal(signalNumber);
  }
}

// The terminal saves and restores the shell's screen around the viewer (smcup).
bool HasAlternateScreen() {
  const char* enter = tigetstr("smcup");
  return enter != nullptr && enter != reinterpret_cast<char*>(-1) && *enter != '\0';
}

}  // namespace

std::optional<std::string> TerminalProblem() {
  const char* term = std::getenv("TERM");
  if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
    return "the viewer needs a terminal (stdin and stdout are not both one)";
  }
  if (term == nullptr || *term == '\0' || std::strcmp(term, "dumb") == 0) {
    return "the viewer needs a terminal that can move the cursor (TERM is unset or dumb)";
  }
  return std::nullopt;
}

TerminalSession::TerminalSession() {
  if (pipe(signalPipe_) != 0) return;
  for (int fd : signalPipe_) {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
  // A short escape delay makes a lone Esc quick; ncurses reads it at newterm.
  setenv("ESCDELAY", "25", 0);
  gFatalRestore.modesSaved = tcgetattr(STDIN_FILENO, &gFatalRestore.savedModes) == 0;

  SCREEN* screen = newterm(nullptr, stdout, stdin);
  if (screen == nullptr) return;
  screen_ = screen;
  set_term(screen);
  InstallSignalHandlers();
  cbreak();
  noecho();
  nonl();
  curs_set(0);
  WINDOW* pad = newpad(1, 1);
  if (pad == nullptr) return;
  inputPad_ = pad;
  keypad(pad, TRUE);
  nodelay(pad, TRUE);
  // No typeahead check: ncurses would flush and poll stdin after every line.
  typeahead(-1);
  mousemask(BUTTON1_PRESSED | BUTTON1_RELEASED | REPORT_MOUSE_POSITION | BUTTON4_PRESSED |
                BUTTON5_PRESSED,
            nullptr);
  mouseinterval(0);
  // ncurses asks for the reports (and turns them off at endwin); the viewer
  // decodes them (InputDecoder): ncurses' decoding keeps only the last of a burst.
  keyok(KEY_MOUSE, FALSE);
  if (has_colors()) start_color();
  // The way back for a fatal signal, made now: no allocation in the handler.
  const std::string reset = TerminalWriter::ResetSequence();
  gFatalRestore.resetBytes = std::min(reset.size(), sizeof gFatalRestore.reset);
  std::memcpy(gFatalRestore.reset, reset.data(), gFatalRestore.resetBytes);
  InstallFatalHandlers();
  fatalHandlersInstalled_ = true;
  gFatalRestore.armed.store(true);
}

int TerminalSession::NextKey() {
  return wgetch(static_cast<WINDOW*>(inputPad_));
}

int TerminalSession::NextKeyWithin(int milliseconds) {
  auto* const pad = static_cast<WINDOW*>(inputPad_);
  wtimeout(pad, milliseconds);
  const int key = wgetch(pad);
  wtimeout(pad, 0);
  return key;
}
int TerminalSession::OutputQueuedBytes() {
  int queued = 0;
  return ioctl(STDOUT_FILENO, TIOCOUTQ, &queued) == 0 ? queued : 0;
}

int TerminalSession::WidthCells() {
  return COLS;
}
int TerminalSession::HeightCells() {
  return LINES;
}

TerminalSession::~TerminalSession() {
  gFatalRestore.armed.store(false);
  if (fatalHandlersInstalled_) RestoreFatalHandlers();
  if (inputPad_ != nullptr) delwin(static_cast<WINDOW*>(inputPad_));
  if (screen_ != nullptr) {
    mousemask(0, nullptr);
    // Without an alternate screen the last frame would stay among the shell's lines.
    if (!HasAlternateScreen()) {
      clear();
      refresh();
    }
    endwin();
    delscreen(static_cast<SCREEN*>(screen_));
    RestoreSignalHandlers();
  }

  gSignalWriteFd.store(-1);
  for (int fd : signalPipe_) {
    if (fd >= 0) close(fd);
  }
}

void TerminalSession::InstallSignalHandlers() {
  gSignalWriteFd.store(signalPipe_[1]);
  struct sigaction action {};
  action.sa_handler = OnHandledSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a signal wakes the event loop's poll
  for (int signalNumber : kHandledSignals) sigaction(signalNumber, &action, nullptr);
}

void TerminalSession::RestoreSignalHandlers() {
  for (int signalNumber : kHandledSignals) std::signal(signalNumber, SIG_DFL);
}

void TerminalSession::InstallFatalHandlers() {
  stack_t alternate{};
  alternate.ss_sp = gAlternateStack;
  alternate.ss_size = sizeof gAlternateStack;
  sigaltstack(&alternate, nullptr);
  struct sigaction action {};
  action.sa_handler = OnFatalSignal;
  sigfillset(&action.sa_mask);  // nothing else runs while the terminal is put back
  action.sa_flags = SA_ONSTACK;
  ForEachFatalSignal([&](int signalNumber) {
    struct sigaction previous {};
    // A signal the caller ignored (nohup, a shell's SIGPIPE) stays ignored.
    if (sigaction(signalNumber, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) return;
    sigaction(signalNumber, &action, nullptr);
  });
}

void TerminalSession::RestoreFatalHandlers() {
  ForEachFatalSignal([](int signalNumber) {
    struct sigaction previous {};
    if (sigaction(signalNumber, nullptr, &previous) == 0 && previous.sa_handler == OnFatalSignal) {
      std::signal(signalNumber, SIG_DFL);
    }
  });
}

int TerminalSession::ReRaise(int signalNumber) {
  std::fflush(nullptr);
  std::signal(signalNumber, SIG_DFL);
  sigset_t unblock;
  sigemptyset(&unblock);
  sigaddset(&unblock, signalNumber);
  sigprocmask(SIG_UNBLOCK, &unblock, nullptr);
  raise(signalNumber);
  return 128 + signalNumber;
}

TerminalSession::Signals TerminalSession::TakeSignals() {
  Signals taken;
  char buffer[16];
  for (ssize_t n; (n = read(signalPipe_[0], buffer, sizeof buffer)) > 0;) {
    for (ssize_t i = 0; i < n; ++i) {
      const int signalNumber = static_cast<unsigned char>(buffer[i]);
      if (signalNumber == SIGTSTP) {
        taken.suspend = true;
      } else if (signalNumber == SIGCONT) {
        taken.resumed = true;
      } else {
        taken.terminate = signalNumber;
      }
    }
  }
  return taken;
}

void TerminalSession::Suspend() {
  // Step 1: the terminal back as the shell had it (endwin: modes, mouse, cursor).
  gFatalRestore.armed.store(false);
  endwin();
  // Step 2: stop for real, as SIGTSTP's default action does; fg continues here.
  std::signal(SIGTSTP, SIG_DFL);
  raise(SIGTSTP);
  InstallSignalHandlers();
  // Step 3: the viewer's modes again (doupdate restores them, with mouse and keypad;
  // its mouse resume turns ncurses' decoding back on).
  doupdate();
  keyok(KEY_MOUSE, FALSE);
  gFatalRestore.armed.store(true);
}

double TerminalSession::ReportedCellAspect() {
  winsize size{};
  if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) != 0) return 0.0;
  if (size.ws_xpixel == 0 || size.ws_ypixel == 0 || size.ws_col == 0 || size.ws_row == 0) {
    return 0.0;
  }
  const double cellWidth = static_cast<double>(size.ws_xpixel) / size.ws_col;
  const double cellHeight = static_cast<double>(size.ws_ypixel) / size.ws_row;
  const double aspect = cellHeight / cellWidth;
  return aspect >= 0.5 && aspect <= 4.0 ? aspect : 0.0;
}

}  // namespace termshade
