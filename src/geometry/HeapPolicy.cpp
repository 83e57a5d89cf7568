#include "geometry/HeapPolicy.h"

#include <climits>  // first: it defines __GLIBC__

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace termshade {

void KeepFreedMemoryForReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
#endif
}

void ReturnFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace termshade
