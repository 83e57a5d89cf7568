#include "io/write/OutputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace termshade {
namespace {

std::string Why(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

}  // namespace

OutputFile::~OutputFile() {
  if (fd_ >= 0) close(fd_);
  if (!temporaryPath_.empty()) unlink(temporaryPath_.c_str());
}

std::optional<std::string> OutputFile::Open() {
  // Step 1: something that is not a regular file is written in place.
  struct stat target {};
  const bool exists = stat(path_.c_str(), &target) == 0;
  if (exists && !S_ISREG(target.st_mode)) {
    if (S_ISDIR(target.st_mode)) return "cannot write: it is a folder";
    fd_ = open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) return Why("cannot write");
    return std::nullopt;
  }
  // Step 2: a temporary file beside the target, with the target's permissions.
  const size_t slash = path_.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : path_.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path_ : path_.substr(slash + 1);
  std::string pattern = (slash == std::string::npos ? "" : folder) + "." + name + ".XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  fd_ = mkostemp(buffer.data(), O_CLOEXEC);
  if (fd_ < 0) return Why("cannot write");
  temporaryPath_ = buffer.data();
  mode_t mode = 0;
  if (exists) {
    mode = target.st_mode & 07777;
  } else {
    const mode_t mask = umask(0);
    umask(mask);
    mode = 0666 & ~mask;
  }
  if (fchmod(fd_, mode) != 0) return Why("cannot write");
  return std::nullopt;
}

std::optional<std::string> OutputFile::Write(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = write(fd_, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return Why("writing failed");
    bytes.remove_prefix(static_cast<size_t>(written));
  }
  return std::nullopt;
}

std::optional<std::string> OutputFile::Commit() {
  if (!temporaryPath_.empty() && fsync(fd_) != 0) return Why("writing failed");
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) return Why("writing failed");
  if (temporaryPath_.empty()) return std::nullopt;
  if (rename(temporaryPath_.c_str(), path_.c_str()) != 0) return Why("cannot replace the file");
  temporaryPath_.clear();
  return std::nullopt;
}

bool SameFile(const std::string& a, const std::string& b) {
  struct stat first {
  }, second{};
  return stat(a.c_str(), &first) == 0 && stat(b.c_str(), &second) == 0 &&
         first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

}  // namespace termshade
