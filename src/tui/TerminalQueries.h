#pragma once

#include <optional>
#include <string_view>

#include "shade/Background.h"
#include "tui/TerminalReply.h"

namespace termshade {

/// What the viewer asks the terminal at start-up, in one write before the
/// DA1 request (FramePacer::kRequest), which every terminal answers last:
/// the background colour (OSC 11), whether it has 24-bit colour (XTGETTCAP
/// of `RGB` and of `Tc`, hex-encoded), and its cell size in pixels (CSI 16 t).
/// A terminal that knows none of them answers only the DA1 request.
inline constexpr std::string_view kStartupQueries =
    "\x1b]11;?\x1b\\"
    "\x1bP+q524742\x1b\\"
    "\x1bP+q5463\x1b\\"
    "\x1b[16t";

/// The longest the viewer waits at start-up for the answers, the DA1 one
/// ending the wait sooner.
inline constexpr int kStartupAnswerWaitMs = 100;

/// What the answers said; nothing where no answer came.
struct TerminalAnswers {
  std::optional<Background> background;
  bool directColour = false;  ///< RGB or Tc: 24-bit colour
  double cellAspect = 0.0;    ///< cell height / width in pixels; 0 when not said
};

/// Adds one answer to what is known.
void TakeReply(const TerminalReply& reply, TerminalAnswers& answers);

/// Light when the colour is nearer white than black in WCAG contrast
/// (relative luminance above about 0.18), else dark.
Background BackgroundOfColour(double red, double green, double blue);

}  // namespace termshade
