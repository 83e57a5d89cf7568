#pragma once

#include <cstddef>

namespace termshade {

/// Makes big arrays come from the heap and stay there once freed, instead of
/// fresh zeroed pages from mmap for each: a big model's load frees and
/// allocates hundreds of MB in turn, and on this kind of VM the kernel's page
/// zeroing was a third of the load (docs/load-and-memory.md, "Heap policy"). One arena serves
/// every thread: a second arena's free top stays resident (malloc_trim frees
/// only the main heap's top), so a job abandoned on a worker thread kept tens
/// of MB after the viewer dropped its model. Call once at start, before any
/// thread (glibc fixes the arena limit at a thread's first malloc).
void KeepFreedMemoryForReuse();

/// Before a big load: makes the heap hold at least `bytes` (address space
/// only, nothing is touched) and asks for huge pages on all of it, so every
/// array the load allocates there, small ones included, faults in 2 MiB at a
/// time (one fault instead of 512; HugePages.h). Arrays outside it (a
/// thread's arena, a heap already bigger) are unaffected.
void AdviseHugePagesForLoad(size_t bytes);

/// Hands the free heap pages back to the kernel (after a long-lived process
/// drops a big model, e.g. the viewer opening a smaller one).
void ReturnFreedMemory();

}  // namespace termshade
