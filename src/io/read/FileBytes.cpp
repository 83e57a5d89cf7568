#include "io/read/FileBytes.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "io/read/FileMapGuard.h"
#include "io/read/RegularFile.h"
#include "process/HugePages.h"

namespace termshade {

FileBytes::FileBytes(FileBytes&& other) noexcept
    : text_(std::move(other.text_)),
      mapped_(other.mapped_),
      mappedBytes_(other.mappedBytes_),
      guardSlot_(other.guardSlot_),
      fd_(other.fd_),
      opened_(other.opened_),
      shrank_(other.shrank_),
      copiedShort_(other.copiedShort_.load()),
      changed_(other.changed_) {
  other.mapped_ = nullptr;
  other.mappedBytes_ = 0;
  other.guardSlot_ = -1;
  other.fd_ = -1;
}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
  if (this == &other) return *this;
  Free();
  text_ = std::move(other.text_);
  mapped_ = other.mapped_;
  mappedBytes_ = other.mappedBytes_;
  guardSlot_ = other.guardSlot_;
  fd_ = other.fd_;
  opened_ = other.opened_;
  shrank_ = other.shrank_;
  copiedShort_ = other.copiedShort_.load();
  changed_ = other.changed_;
  other.mapped_ = nullptr;
  other.mappedBytes_ = 0;
  other.guardSlot_ = -1;
  other.fd_ = -1;
  return *this;
}

Loaded<FileBytes> FileBytes::MapRegularFile(
    const std::string& path, const std::function<std::optional<std::string>(size_t)>& refuseSize,
    const std::atomic<bool>* cancel) {
  // Step 1: open without blocking and look at what it is (as ReadRegularFile).
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return LoadError{path, 0, 0, std::string("cannot open: ") + std::strerror(errno)};
  struct stat info {};
  const bool statted = fstat(fd, &info) == 0;
  const bool mappable = statted && S_ISREG(info.st_mode) && info.st_size > 0;
  void* mapped = MAP_FAILED;
  if (mappable && !refuseSize(static_cast<size_t>(info.st_size))) {
    mapped = mmap(nullptr, static_cast<size_t>(info.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
  }
  // A mapped file stays open, to be compared with info when it is freed.
  if (mapped == MAP_FAILED) close(fd);
  // Step 2: anything not mapped (refused, empty, not regular, no mapping or
  // no watch slot) is read instead, which gives the message where one is due.
  const auto readInstead = [&]() -> Loaded<FileBytes> {
    Loaded<std::string> text = ReadRegularFile(path, refuseSize, cancel);
    if (!text.Ok()) return text.Error();
    return FileBytes(std::move(text.Value()));
  };
  if (mapped == MAP_FAILED) return readInstead();
  const auto size = static_cast<size_t>(info.st_size);
  const int slot = WatchMappedRange(mapped, size);
  if (slot < 0) {
    munmap(mapped, size);
    close(fd);
    return readInstead();
  }
  // Read ahead now where the file is not cached yet.
  madvise(mapped, size, MADV_WILLNEED);
  FileBytes bytes;
  if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
    StopWatchingMappedRange(slot);
    munmap(mapped, size);
    close(fd);
    return LoadError{path, 0, 0, "loading cancelled"};
  }
  bytes.mapped_ = static_cast<const char*>(mapped);
  bytes.mappedBytes_ = size;
  bytes.guardSlot_ = slot;
  bytes.fd_ = fd;
  bytes.opened_ = info;
  return bytes;
}

std::string_view FileBytes::View() const {
  if (mapped_ != nullptr) return {mapped_, mappedBytes_};
  return text_;
}

void FileBytes::CopyOut(size_t offset, size_t count, char* dest) const {
  const size_t size = Size();
  const size_t inside = offset < size ? std::min(count, size - offset) : 0;
  size_t copied = 0;
  if (mapped_ == nullptr) {
    std::memcpy(dest, text_.data() + offset, inside);
    copied = inside;
  } else {
    while (copied < inside) {
      const ssize_t got =
          pread(fd_, dest + copied, inside - copied, static_cast<off_t>(offset + copied));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) break;  // the file's end, or an error (EIO)
      copied += static_cast<size_t>(got);
    }
  }
  if (copied < count) {
    std::memset(dest + copied, 0, count - copied);
    copiedShort_.store(true, std::memory_order_relaxed);
  }
}

void FileBytes::Release(size_t begin, size_t end) {
  if (mapped_ == nullptr) {
    if (end > begin && end <= text_.size()) ReleasePages(text_.data() + begin, end - begin);
    return;
  }
  if (end <= begin || end > mappedBytes_) return;
  const auto pageBytes = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto base = reinterpret_cast<uintptr_t>(mapped_);
  const uintptr_t first = (base + begin + pageBytes - 1) & ~(pageBytes - 1);
  const uintptr_t last = (base + end) & ~(pageBytes - 1);
  // A private mapping never written: the pages leave this process, the
  // page cache keeps them.
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
}

void FileBytes::Free() {
  if (mapped_ != nullptr) {
    // Everything read from the mapping was read before this.
    changed_ = changed_ || StatChanged();
    shrank_ = StopWatchingMappedRange(guardSlot_) || shrank_;
    munmap(const_cast<char*>(mapped_), mappedBytes_);
    mapped_ = nullptr;
    mappedBytes_ = 0;
    guardSlot_ = -1;
  }
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
  FreeAndReleasePages(text_);
}

std::string FileBytes::TakeString() {
  if (mapped_ == nullptr) return std::move(text_);
  std::string text(View());
  Free();
  return text;
}

bool FileBytes::Shrank() const {
  return shrank_ || copiedShort_.load(std::memory_order_relaxed) ||
         (mapped_ != nullptr && MappedRangeShrank(guardSlot_));
}

bool FileBytes::ChangedSinceOpened() const {
  return changed_ || (mapped_ != nullptr && StatChanged());
}

bool FileBytes::StatChanged() const {
  if (fd_ < 0) return false;
  struct stat now {};
  if (fstat(fd_, &now) != 0) return true;
  return now.st_size != opened_.st_size || now.st_ino != opened_.st_ino ||
         now.st_dev != opened_.st_dev || now.st_mtim.tv_sec != opened_.st_mtim.tv_sec ||
         now.st_mtim.tv_nsec != opened_.st_mtim.tv_nsec ||
         now.st_ctim.tv_sec != opened_.st_ctim.tv_sec ||
         now.st_ctim.tv_nsec != opened_.st_ctim.tv_nsec;
}

}  // namespace termshade
