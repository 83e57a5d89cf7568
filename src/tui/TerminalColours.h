#pragma once

#include "shade/ColourMode.h"

namespace termshade {

/// What `--color auto` means here: AutoColourMode from NO_COLOR, COLORTERM
/// and the terminfo entry of TERM (its colour count and direct-colour flags).
ColourMode DetectColourMode();

/// The most colour the terminal has, NO_COLOR aside: AutoColourMode from
/// COLORTERM and the terminfo entry of TERM.
ColourMode DetectTerminalColourMode();

/// mode itself, or DetectColourMode() for kAuto.
ColourMode ResolveColourMode(ColourMode mode);

}  // namespace termshade
