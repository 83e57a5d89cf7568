#include "tui/PromptPath.h"

namespace termshade {

std::string PromptPath(std::string_view typed, std::string_view homeDirectory) {
  // Step 1: blanks around the path.
  const size_t first = typed.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  std::string_view path = typed.substr(first, typed.find_last_not_of(" \t") - first + 1);
  // Step 2: one pair of enclosing quotes.
  if (path.size() >= 2 && (path.front() == '\'' || path.front() == '"') &&
      path.back() == path.front()) {
    path = path.substr(1, path.size() - 2);
  }
  // Step 3: the home directory.
  if (!homeDirectory.empty() && (path == "~" || path.substr(0, 2) == "~/")) {
    return std::string(homeDirectory) + std::string(path.substr(1));
  }
  return std::string(path);
}

}  // namespace termshade
