#include "process/HeapPolicy.h"

#include <climits>  // first: it defines __GLIBC__
#include <cstdlib>

#include "process/HugePages.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace termshade {

void KeepFreedMemoryForReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
  mallopt(M_ARENA_MAX, 1);
#endif
}

void AdviseHugePagesForLoad(size_t bytes) {
  // Freed, the block joins the heap's free top (kept: KeepFreedMemoryForReuse)
  // with its advice; untouched, it costs no memory.
  void* block = std::malloc(bytes);
  if (block == nullptr) return;
  AdviseHugePages(block, bytes);
  std::free(block);
}

void ReturnFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace termshade
