#pragma once

namespace termshade {

/// Fills standard input, output and error where they were closed at start
/// (`>&-`) with /dev/null opened read-only: no file the program opens later
/// takes their place (frames would go into it), and every write to a closed
/// one fails at once (EBADF) instead of succeeding. Call once at start,
/// before any other file is opened.
void GuardClosedStandardDescriptors();

}  // namespace termshade
