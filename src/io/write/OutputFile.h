#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// A file replaced whole or not at all: bytes go to a temporary file in the
/// same folder, renamed over the target only once everything was written and
/// synced, so a full disk or a failed run leaves the previous file as it was.
/// A target that exists and is not a regular file (a FIFO, /dev/stdout, a
/// terminal) is written in place. Errors say why (strerror).
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

 private:
  std::string path_;
  std::string temporaryPath_;  ///< empty when written in place
  int fd_ = -1;
};

/// True when both paths name the same existing file (same device and inode).
bool SameFile(const std::string& a, const std::string& b);

}  // namespace termshade
