#pragma once

#include <string>
#include <string_view>

namespace termshade {

/// The file a path typed (or dropped) at the open prompt names: blanks
/// around it trimmed, one pair of enclosing quotes removed (terminals add
/// them when a file is dragged in), and a leading "~" or "~/" replaced by
/// homeDirectory (when it is not empty).
std::string PromptPath(std::string_view typed, std::string_view homeDirectory);

}  // namespace termshade
