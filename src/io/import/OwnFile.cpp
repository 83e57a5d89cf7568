#include "io/import/OwnFile.h"

#include <sys/stat.h>
#include <unistd.h>

namespace termshade {
namespace {

// This program's own folder, from /proc/self/exe; empty when unreadable.
std::string ExecutableFolder() {
  std::string path(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", path.data(), path.size());
  if (length <= 0 || static_cast<size_t>(length) >= path.size()) return "";
  path.resize(static_cast<size_t>(length));
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos || path.front() != '/' ? "" : path.substr(0, slash);
}

bool IsRegularFile(const std::string& path) {
  struct stat info {};
  return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

}  // namespace

OwnFile FindOwnFile(const std::string& name, const std::string& what) {
  const std::string folder = ExecutableFolder();
  if (folder.empty()) {
    return {"", "cannot find " + what + " " + name +
                    ": this program's own path (/proc/self/exe) cannot be read"};
  }
  const std::string installed = folder + "/" TERMSHADE_MODULE_FROM_BINDIR "/" + name;
  const std::string buildTree = folder + "/" + name;
  if (IsRegularFile(installed)) return {installed, ""};
  if (IsRegularFile(buildTree)) return {buildTree, ""};
  return {"", what + " " + name + " is missing (looked for " + installed + " and " + buildTree +
                  "); reinstall termshade"};
}

}  // namespace termshade
