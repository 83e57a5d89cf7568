#pragma once

#include <cstddef>
#include <vector>

namespace termshade {

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes)
/// with huge pages when they are first touched: one page fault instead of
/// 512 for each. Only worth it before the memory is written; a no-op for
/// ranges under 4 MiB and where the kernel declines.
void AdviseHugePages(void* data, size_t bytes);

/// The same for a vector's whole capacity (reserve first, then fill).
template <typename T>
void AdviseHugePages(std::vector<T>& values) {
  AdviseHugePages(values.data(), values.capacity() * sizeof(T));
}

}  // namespace termshade
