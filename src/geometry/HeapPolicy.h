#pragma once

namespace termshade {

/// Makes big arrays come from the heap and stay there once freed, instead of
/// fresh zeroed pages from mmap for each: a big model's load frees and
/// allocates hundreds of MB in turn, and on this kind of VM the kernel's page
/// zeroing was a third of the load (README, "Big models"). Call once at start.
void KeepFreedMemoryForReuse();

/// Hands the free heap pages back to the kernel (after a long-lived process
/// drops a big model, e.g. the viewer opening a smaller one).
void ReturnFreedMemory();

}  // namespace termshade
