#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// A file replaced whole or not at all: bytes go to a temporary file beside
/// the target, renamed over it only once everything was written and synced,
/// so a full disk or a failed run leaves the previous file as it was.
/// Symbolic links are followed to their final target, which is replaced
/// beside itself: a link is never replaced. A target that is not a regular
/// file (a FIFO, a terminal, a device, /dev/stdout onto a pipe) is written in
/// place, as is a regular file whose folder cannot take a temporary file
/// (/proc/self/fd/1 onto a deleted file, a read-only folder): InPlaceReason
/// then says why. Errors say why (strerror).
class OutputFile {
 public:
  explicit OutputFile(std::string path) : path_(std::move(path)) {}
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Removes the temporary file if Commit was not reached.
  ~OutputFile();

  /// Each returns nullopt on success, else the message (without the path).
  std::optional<std::string> Open();
  std::optional<std::string> Write(std::string_view bytes);
  std::optional<std::string> Commit();

  /// Set by Open when a regular file is written in place rather than
  /// replaced whole: why (for a note to the user); empty otherwise.
  const std::string& InPlaceReason() const { return inPlaceReason_; }
  /// The file that is written or replaced: the path with its links followed.
  const std::string& TargetPath() const { return targetPath_; }

 private:
  std::optional<std::string> OpenInPlace(bool truncate);

  std::string path_;
  std::string targetPath_;     ///< path_ with its symbolic links followed
  std::string temporaryPath_;  ///< empty when written in place
  std::string inPlaceReason_;
  int fd_ = -1;
};

/// Follows the symbolic links of path (each a link's text, relative to the
/// link's folder) to what the last one names, which need not exist; nullopt
/// past 40 links (a loop). The folders on the way are not resolved.
std::optional<std::string> FollowLinks(const std::string& path);

/// Writes all of bytes to fd (again after a short write or EINTR); nullopt on
/// success, else "writing failed: " and why (EPIPE, EBADF, ENOSPC).
std::optional<std::string> WriteWhole(int fd, std::string_view bytes);

/// True when both paths name the same existing file (same device and inode).
bool SameFile(const std::string& a, const std::string& b);

}  // namespace termshade
