#include "process/HugePages.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace termshade {

void AdviseHugePages(void* data, size_t bytes) {
  constexpr uintptr_t kHugePage = uintptr_t{1} << 21;
  if (data == nullptr || bytes < 2 * kHugePage) return;
  const auto begin = reinterpret_cast<uintptr_t>(data);
  const uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (last <= first) return;
  // Advice only: where the kernel has no huge pages, the range stays as it was.
  madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

void ReleasePages(void* data, size_t bytes) {
  const auto pageBytes = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto begin = reinterpret_cast<uintptr_t>(data);
  const uintptr_t first = (begin + pageBytes - 1) & ~(pageBytes - 1);
  const uintptr_t last = (begin + bytes) & ~(pageBytes - 1);
  if (data == nullptr || last <= first) return;
  madvise(static_cast<char*>(data) + (first - begin), last - first, MADV_DONTNEED);
}

}  // namespace termshade
