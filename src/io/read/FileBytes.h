#pragma once

#include <sys/stat.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "io/read/LoadError.h"

namespace termshade {

/// What a load of a file that changed while it was read says: its bytes
/// differed between two reads, or its size or times from when it was opened.
inline constexpr const char* kFileChangedMessage = "the file changed while it was read";
/// What a load says when pages of a mapped file could not be read
/// (FileBytes::Shrank): the file shrank, or reading them failed (EIO).
inline constexpr const char* kFilePagesLostMessage =
    "the file changed while it was read, or a part of it could not be read";

/// A model file's bytes: held in a string (standard input, tests), or mapped
/// read-only from a regular file, so the load neither zeroes nor copies
/// memory for them (on this kind of machine fresh memory costs about 1 ms a
/// MB to fault in, the page cache's pages a tenth of that).
/// A mapped file that shrinks while it is read would raise SIGBUS at the
/// pages past its new end; a guard (FileMapGuard.h) maps zeros there instead
/// and marks the bytes Shrank(), which the loader turns into an error. The
/// file stays open while mapped: ChangedSinceOpened() compares its size,
/// times, inode and device with those it had when it was opened (a change
/// inside the last page, or a rewrite, raises no SIGBUS).
class FileBytes {
 public:
  FileBytes() = default;
  explicit FileBytes(std::string text) : text_(std::move(text)) {}
  FileBytes(FileBytes&& other) noexcept;
  FileBytes& operator=(FileBytes&& other) noexcept;
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;
  ~FileBytes() { Free(); }

  /// Maps a regular file (O_NONBLOCK, fstat first: a FIFO, device, socket or
  /// folder is refused at once). refuseSize sees the size before anything is
  /// mapped and may refuse it with a message. A load already cancelled
  /// (cancel may be null) is "loading cancelled".
  static Loaded<FileBytes> MapRegularFile(
      const std::string& path, const std::function<std::optional<std::string>(size_t)>& refuseSize,
      const std::atomic<bool>* cancel = nullptr);

  std::string_view View() const;
  size_t Size() const { return View().size(); }
  bool Mapped() const { return mapped_ != nullptr; }

  /// Copies the bytes [offset, offset + count) to dest, for a reader that
  /// reads each byte once, in pieces: from a mapped file with pread on its
  /// descriptor, so the kernel copies from the page cache and the mapping's
  /// pages are never faulted in (on this kind of machine about 3 times
  /// cheaper than reading them through the mapping); else from the held
  /// bytes. Bytes the file no longer has (it shrank, or reading failed) are
  /// zeros and make Shrank() true. Safe on several threads at once.
  void CopyOut(size_t offset, size_t count, char* dest) const;
  /// Hands back the memory of the whole pages inside [begin, end) (byte
  /// offsets): bytes already parsed that will not be read again. They read
  /// as zeros (held) or as the file again (mapped) if they are.
  void Release(size_t begin, size_t end);
  /// Frees the bytes (empty after); Shrank() keeps its answer.
  void Free();
  /// The bytes in a string (a mapping is copied, then freed), for the importer.
  std::string TakeString();
  /// Pages of a mapped file could not be read (it shrank, or an I/O error):
  /// some bytes read were zeros, not the file's.
  bool Shrank() const;
  /// A mapped file's size, modification or change time, inode or device
  /// differ from when it was opened (now, or when it was freed).
  bool ChangedSinceOpened() const;

 private:
  bool StatChanged() const;

  std::string text_;
  const char* mapped_ = nullptr;
  size_t mappedBytes_ = 0;
  int guardSlot_ = -1;
  int fd_ = -1;
  struct stat opened_ {};
  bool shrank_ = false;
  mutable std::atomic<bool> copiedShort_{false};  ///< CopyOut met the file's end or an error
  bool changed_ = false;
};

}  // namespace termshade
