#include "io/load/TextureReferences.h"

#include <fcntl.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace termshade {
namespace {

bool IsInside(const std::string& path, const std::string& folder) {
  return path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
         path[folder.size()] == '/';
}

TextureWhere Locate(std::string name, const std::string& folder) {
  // Step 1: names that are not files in a folder.
  if (name.front() == '*') return TextureWhere::kEmbedded;
  if (name.find('\0') != std::string::npos) return TextureWhere::kMissing;  // no such file name
  if (name.rfind("file:", 0) == 0 || name.rfind("data:", 0) == 0 ||
      name.find("://") != std::string::npos) {
    return TextureWhere::kUri;
  }
  if (folder.empty()) return TextureWhere::kNoFolder;
  std::replace(name.begin(), name.end(), '\\', '/');  // files written on Windows
  if (name.front() == '/' || (name.size() > 1 && name[1] == ':')) {
    return TextureWhere::kOutsideFolder;
  }
  // Step 2: where it really is (links and '..' resolved), looked up only inside.
  std::error_code error;
  const std::string resolved =
      std::filesystem::weakly_canonical(std::filesystem::path(folder) / name, error).string();
  if (error || !IsInside(resolved, folder)) return TextureWhere::kOutsideFolder;
  // Not through a link swapped in since (it would tell of a file outside).
  struct stat status {};
  return fstatat(AT_FDCWD, resolved.c_str(), &status, AT_SYMLINK_NOFOLLOW) == 0 &&
                 S_ISREG(status.st_mode)
             ? TextureWhere::kInFolder
             : TextureWhere::kMissing;
}

}  // namespace

std::string_view TextureWhereName(TextureWhere where) {
  switch (where) {
    case TextureWhere::kEmbedded:
      return "embedded";
    case TextureWhere::kInFolder:
      return "found";
    case TextureWhere::kMissing:
      return "missing";
    case TextureWhere::kOutsideFolder:
      return "outside the model's folder (not looked at)";
    case TextureWhere::kUri:
      return "a URI (not looked at)";
    case TextureWhere::kNoFolder:
      return "standard input has no folder (not looked at)";
  }
  return "missing";
}

std::vector<TextureReference> LocateTextures(const std::vector<std::string>& names,
                                             const std::string& modelPath) {
  std::string folder;
  if (modelPath != "-") {
    std::error_code error;
    const std::filesystem::path model = std::filesystem::weakly_canonical(modelPath, error);
    if (!error) folder = model.parent_path().string();
  }
  std::vector<TextureReference> references;
  for (const std::string& name : names) {
    if (name.empty()) continue;
    references.push_back({name, Locate(name, folder)});
  }
  return references;
}

}  // namespace termshade
