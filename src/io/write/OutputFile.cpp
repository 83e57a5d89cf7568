#include "io/write/OutputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <vector>

namespace termshade {
namespace {

std::string Why(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

// The folder part of a path with its slash ("a/b/" of "a/b/c"); empty for a bare name.
std::string FolderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

bool SameInode(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace

std::optional<std::string> FollowLinks(const std::string& path) {
  constexpr int kMostLinks = 40;  // the kernel's own limit (ELOOP)
  std::string current = path;
  for (int hop = 0; hop <= kMostLinks; ++hop) {
    struct stat status {};
    if (lstat(current.c_str(), &status) != 0 || !S_ISLNK(status.st_mode)) return current;
    std::vector<char> text(PATH_MAX + 1);
    const ssize_t length = readlink(current.c_str(), text.data(), text.size() - 1);
    if (length <= 0) return current;
    std::string next(text.data(), static_cast<size_t>(length));
    current = next.front() == '/' ? next : FolderOf(current) + next;
  }
  return std::nullopt;
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) close(fd_);
  if (!temporaryPath_.empty()) unlink(temporaryPath_.c_str());
}

std::optional<std::string> OutputFile::OpenInPlace(bool truncate) {
  fd_ = open(targetPath_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY | (truncate ? O_TRUNC : 0));
  if (fd_ < 0) return Why("cannot write");
  return std::nullopt;
}

std::optional<std::string> OutputFile::Open() {
  if (path_.empty()) return "cannot write: the file name is empty";
  // Step 1: what the path names, its links followed. Something that is not a
  // regular file (a FIFO, a terminal, a device, /dev/stdout onto a pipe) is
  // written in place, through the path as given.
  struct stat target {};
  const bool exists = stat(path_.c_str(), &target) == 0;
  if (!exists && errno != ENOENT) return Why("cannot write");
  if (exists && S_ISDIR(target.st_mode)) return "cannot write: it is a folder";
  targetPath_ = path_;
  if (exists && !S_ISREG(target.st_mode)) return OpenInPlace(false);

  // Step 2: the file the links lead to, replaced beside itself (never the
  // link). A link whose text is no path to the file (/proc/self/fd/1 onto a
  // deleted file) leaves no folder for a temporary file: in place.
  const auto followed = FollowLinks(path_);
  if (!followed) return "cannot write: too many levels of symbolic links";
  targetPath_ = *followed;
  struct stat atTarget {};
  const bool targetExists = lstat(targetPath_.c_str(), &atTarget) == 0;
  if (exists && (!targetExists || !SameInode(target, atTarget))) {
    targetPath_ = path_;
    inPlaceReason_ = "its links lead to no folder a temporary file could be made in";
    return OpenInPlace(true);
  }
  if (!exists && targetExists) return "cannot write: it changed while being opened";

  // Step 3: a temporary file beside the target, with the target's permissions;
  // where none can be made beside an existing file (a folder that is not
  // writable), the file is written in place.
  const std::string name = targetPath_.substr(FolderOf(targetPath_).size());
  std::string pattern = FolderOf(targetPath_) + "." + name + ".XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  fd_ = mkostemp(buffer.data(), O_CLOEXEC);
  if (fd_ < 0 && exists && (errno == EACCES || errno == EPERM)) {
    inPlaceReason_ = Why("no temporary file can be made beside it");
    return OpenInPlace(true);
  }
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

std::optional<std::string> WriteWhole(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return Why("writing failed");
    bytes.remove_prefix(static_cast<size_t>(written));
  }
  return std::nullopt;
}

std::optional<std::string> OutputFile::Write(std::string_view bytes) {
  return WriteWhole(fd_, bytes);
}

std::optional<std::string> OutputFile::Commit() {
  if (!temporaryPath_.empty() && fsync(fd_) != 0) return Why("writing failed");
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) return Why("writing failed");
  if (temporaryPath_.empty()) return std::nullopt;
  // The target became a link or a special file while the frames were drawn:
  // left as it is (rename would replace it).
  struct stat atTarget {};
  if (lstat(targetPath_.c_str(), &atTarget) == 0 && !S_ISREG(atTarget.st_mode)) {
    return "cannot replace the file: it is no longer a regular file";
  }
  if (rename(temporaryPath_.c_str(), targetPath_.c_str()) != 0)
    return Why("cannot replace the file");
  temporaryPath_.clear();
  return std::nullopt;
}

bool SameFile(const std::string& a, const std::string& b) {
  struct stat first {
  }, second{};
  return stat(a.c_str(), &first) == 0 && stat(b.c_str(), &second) == 0 && SameInode(first, second);
}

}  // namespace termshade
