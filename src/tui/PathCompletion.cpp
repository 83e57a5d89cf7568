#include "tui/PathCompletion.h"

#include <filesystem>
#include <system_error>

#include "tui/PromptPath.h"

namespace termshade {
namespace {

constexpr int kMaxEntries = 100000;  // a huge directory is not read to the end

size_t CommonPrefixLength(std::string_view a, std::string_view b) {
  size_t n = 0;
  while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
  return n;
}

}  // namespace

PathCompletion CompletePath(std::string_view typed, std::string_view homeDirectory) {
  PathCompletion result{std::string(typed), 0};
  // Step 1: the directory to read and the name begun in it.
  const std::string path = PromptPath(typed, homeDirectory);
  // Quoted or ending in a blank: left alone (the extension would land after it).
  if (path.empty() || typed.find_first_of("'\"") != std::string_view::npos || typed.back() == ' ' ||
      typed.back() == '\t') {
    return result;
  }
  const size_t slash = path.rfind('/');
  const std::string directory =
      slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const std::string begun = slash == std::string::npos ? path : path.substr(slash + 1);
  // Step 2: the entries that start with it, and what they all share.
  std::error_code error;
  std::filesystem::directory_iterator entries(directory, error);
  std::string shared;
  bool sharedIsDirectory = false;
  int seen = 0;
  for (; !error && entries != std::filesystem::directory_iterator() && seen < kMaxEntries;
       entries.increment(error), ++seen) {
    const std::string name = entries->path().filename().string();
    if (name.compare(0, begun.size(), begun) != 0) continue;
    if (name[0] == '.' && (begun.empty() || begun[0] != '.')) continue;
    shared = result.matches == 0 ? name : shared.substr(0, CommonPrefixLength(shared, name));
    sharedIsDirectory = result.matches == 0 && entries->is_directory(error);
    ++result.matches;
  }
  // Step 3: extend what was typed.
  if (result.matches == 0) return result;
  result.text += shared.substr(begun.size());
  if (result.matches == 1 && sharedIsDirectory) result.text += '/';
  return result;
}

}  // namespace termshade
