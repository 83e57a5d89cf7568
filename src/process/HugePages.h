#pragma once

#include <cstddef>
#include <vector>

namespace termshade {

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes)
/// with huge pages when they are first touched: one page fault instead of
/// 512 for each. Only worth it before the memory is written; a no-op for
/// ranges under 4 MiB and where the kernel declines.
void AdviseHugePages(void* data, size_t bytes);

/// Hands the whole pages inside [data, data + bytes) back to the kernel
/// (MADV_DONTNEED): memory still allocated but no longer read, such as the
/// part of a file already parsed. They read as zeros if touched again.
void ReleasePages(void* data, size_t bytes);

/// Frees a vector or string whose storage came from the heap, handing its
/// pages back first: the heap keeps freed memory (HeapPolicy.h), and a big
/// block's hole would stay resident until something fits in it.
template <typename Container>
void FreeAndReleasePages(Container& values) {
  ReleasePages(values.data(), values.capacity() * sizeof(values[0]));
  Container().swap(values);
}

/// The same for a vector's whole capacity (reserve first, then fill).
template <typename T>
void AdviseHugePages(std::vector<T>& values) {
  AdviseHugePages(values.data(), values.capacity() * sizeof(T));
}

/// Resizes a per-frame buffer to count entries; when it must grow, the new
/// storage is advised first, so its first fill faults in huge pages. The
/// old contents are not kept.
template <typename T>
void ResizeWithHugePages(std::vector<T>& values, size_t count) {
  if (values.capacity() < count) {
    std::vector<T>().swap(values);
    values.reserve(count);
    AdviseHugePages(values);
  }
  values.resize(count);
}

}  // namespace termshade
