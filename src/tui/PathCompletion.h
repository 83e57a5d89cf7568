#pragma once

#include <string>
#include <string_view>

namespace termshade {

/// What Tab does at the open prompt.
struct PathCompletion {
  std::string text;  ///< typed, extended by what all matches share ("/" after a lone directory)
  int matches = 0;   ///< directory entries that start with the typed name
};

/// Completes the last component of a typed path against its directory, as a
/// shell does: `~/` means homeDirectory, names starting with '.' are offered
/// only when the typed name starts with one. The typed text is kept as typed
/// (no expansion) and only extended.
PathCompletion CompletePath(std::string_view typed, std::string_view homeDirectory);

}  // namespace termshade
