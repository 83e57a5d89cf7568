#pragma once

#include "shade/ColourMode.h"

namespace termshade {

/// What `--color auto` means here: AutoColourMode from NO_COLOR, COLORTERM
/// and the terminfo entry of TERM (its colour count and direct-colour flags).
ColourMode DetectColourMode();

/// mode itself, or DetectColourMode() for kAuto.
ColourMode ResolveColourMode(ColourMode mode);

}  // namespace termshade
