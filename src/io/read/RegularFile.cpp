#include "io/read/RegularFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "io/read/FileDescriptor.h"
#include "process/HugePages.h"

namespace termshade {
namespace {

std::string KindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "something else";
}

LoadError Cancelled(const std::string& name) {
  return LoadError{name, 0, 0, "loading cancelled"};
}

// Reads up to size bytes into text from offset; false with errno on a read error.
bool ReadFully(int fd, std::string& text, size_t size, const std::atomic<bool>* cancel,
               bool& cancelled) {
  constexpr size_t kChunkBytes = size_t{4} << 20;
  size_t done = 0;
  while (done < size) {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
      cancelled = true;
      return false;
    }
    const ssize_t got = read(fd, text.data() + done, std::min(kChunkBytes, size - done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return false;
    if (got == 0) break;  // the file shrank while we read it
    done += static_cast<size_t>(got);
  }
  text.resize(done);
  return true;
}

}  // namespace

std::string FormatBytes(double bytes) {
  static constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  char text[48];
  if (unit == 0) {
    std::snprintf(text, sizeof text, "%.0f bytes", bytes);
  } else {
    std::snprintf(text, sizeof text, "%.1f %s", bytes, kUnits[unit]);
  }
  return text;
}

Loaded<std::string> ReadRegularFile(
    const std::string& path, const std::function<std::optional<std::string>(size_t)>& refuseSize,
    const std::atomic<bool>* cancel) {
  // Step 1: open without blocking (a FIFO would wait for a writer) and look at what it is.
  const FileDescriptor fd(open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.Get() < 0)
    return LoadError{path, 0, 0, std::string("cannot open: ") + std::strerror(errno)};
  struct stat info {};
  if (fstat(fd.Get(), &info) != 0) {
    return LoadError{path, 0, 0, std::string("cannot read: ") + std::strerror(errno)};
  }
  if (!S_ISREG(info.st_mode)) {
    return LoadError{path, 0, 0, "not a regular file but " + KindOf(info.st_mode)};
  }
  // Step 2: the size against the limit, before allocating.
  const auto size = static_cast<size_t>(info.st_size);
  if (auto refusal = refuseSize(size)) return LoadError{path, 0, 0, std::move(*refusal)};
  // Step 3: the bytes.
  std::string text;
  text.reserve(size);
  AdviseHugePages(text.data(), size);
  text.resize(size);
  bool cancelled = false;
  if (!ReadFully(fd.Get(), text, size, cancel, cancelled)) {
    if (cancelled) return Cancelled(path);
    return LoadError{path, 0, 0, std::string("cannot read: ") + std::strerror(errno)};
  }
  return text;
}

Loaded<std::string> ReadStream(int fd, const std::string& name, size_t maxBytes,
                               const std::atomic<bool>* cancel) {
  // Read into pieces (1 MiB, doubling to 64 MiB, only the bytes read touched),
  // joined once at the end: at most twice the input is held, never a
  // doubling buffer's copies (which a heap that keeps freed memory would keep too).
  struct Piece {
    std::unique_ptr<char[]> bytes;
    size_t capacity = 0;
    size_t used = 0;
  };
  std::vector<Piece> pieces;
  size_t total = 0;
  constexpr size_t kFirstPieceBytes = size_t{1} << 20, kLargestPieceBytes = size_t{64} << 20;
  while (true) {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) return Cancelled(name);
    if (pieces.empty() || pieces.back().used == pieces.back().capacity) {
      const size_t size = pieces.empty() ? kFirstPieceBytes
                                         : std::min(kLargestPieceBytes, 2 * pieces.back().capacity);
      pieces.push_back({std::make_unique_for_overwrite<char[]>(size), size, 0});
    }
    Piece& piece = pieces.back();
    const ssize_t got = read(fd, piece.bytes.get() + piece.used, piece.capacity - piece.used);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return LoadError{name, 0, 0, std::string("cannot read: ") + std::strerror(errno)};
    if (got == 0) break;
    piece.used += static_cast<size_t>(got);
    total += static_cast<size_t>(got);
    if (total > maxBytes) {
      return LoadError{name, 0, 0,
                       "the input is more than " + FormatBytes(static_cast<double>(maxBytes)) +
                           ", the largest model the memory budget lets load"};
    }
  }
  std::string text;
  text.reserve(total);
  for (Piece& piece : pieces) {
    text.append(piece.bytes.get(), piece.used);
    piece.bytes.reset();
  }
  return text;
}

}  // namespace termshade
