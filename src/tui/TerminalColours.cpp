#include "tui/TerminalColours.h"

#include <curses.h>
#include <term.h>
#include <unistd.h>

#include <cstdlib>

namespace termshade {
namespace {

struct TerminfoColours {
  int count = 0;
  bool direct = false;
};

// TERM's terminfo entry, read without touching the terminal or the current
// terminal description (a running session keeps its own).
TerminfoColours ReadTerminfoColours() {
  TerminfoColours out;
  TERMINAL* const previous = cur_term;
  int status = 0;
  if (setupterm(nullptr, STDOUT_FILENO, &status) != OK) {
    set_curterm(previous);
    return out;
  }
  out.count = tigetnum("colors");
  out.direct = tigetflag("RGB") == 1 || tigetflag("Tc") == 1;
  TERMINAL* const read = set_curterm(previous);
  if (read != previous) del_curterm(read);
  return out;
}

const char* Env(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

}  // namespace

ColourMode DetectColourMode() {
  const TerminfoColours terminfo = ReadTerminfoColours();
  return AutoColourMode(Env("NO_COLOR"), Env("COLORTERM"), terminfo.count, terminfo.direct);
}

ColourMode DetectTerminalColourMode() {
  const TerminfoColours terminfo = ReadTerminfoColours();
  return AutoColourMode("", Env("COLORTERM"), terminfo.count, terminfo.direct);
}

ColourMode ResolveColourMode(ColourMode mode) {
  return mode == ColourMode::kAuto ? DetectColourMode() : mode;
}

}  // namespace termshade
