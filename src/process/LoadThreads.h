#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "process/HugePages.h"

namespace termshade {

/// How many threads a load step of `items` items uses: every core (at most
/// 8), one below kMinItemsPerThread items a thread, where starting a thread
/// costs more than it saves.
int LoadThreadCount(size_t items);

/// Runs work(0) .. work(threads - 1) (nothing for threads < 1), work(0) on the calling thread, the
/// rest on threads started for the call and joined before it returns. The started threads take no
/// signals but their own faults (QuietThreadStart: the viewer's SIGWINCH and SIGINT stay with the
/// thread that waits for input) and work must not allocate or throw there.
void RunOnLoadThreads(int threads, const std::function<void(int)>& work);

/// Splits [0, count) into `threads` ranges in order and runs
/// work(part, begin, end) for each on the load threads (RunOnLoadThreads).
template <typename Work>
void RunRangesOnLoadThreads(int threads, size_t count, const Work& work) {
  RunOnLoadThreads(threads, [&work, threads, count](int part) {
    const auto parts = static_cast<size_t>(threads);
    const auto at = static_cast<size_t>(part);
    work(part, count * at / parts, count * (at + 1) / parts);
  });
}

/// Faults in the whole pages inside [data, data + bytes) now, writable, split
/// over the load threads (MADV_POPULATE_WRITE; the contents stay as they
/// are): the kernel's zeroing of fresh pages, most of what filling a new
/// array costs on this kind of machine, runs on every core instead of on
/// the one thread that fills it. A no-op under 4 MiB or where the kernel
/// lacks it (before Linux 5.14).
void PopulateOnLoadThreads(void* data, size_t bytes);

/// Reserves count entries with huge pages advised, faulted in on the load
/// threads (PopulateOnLoadThreads), then resizes to them: a big array about
/// to be filled.
template <typename T>
void ResizeFaultedIn(std::vector<T>& values, size_t count) {
  values.reserve(count);
  AdviseHugePages(values.data(), values.capacity() * sizeof(T));
  PopulateOnLoadThreads(values.data(), count * sizeof(T));
  values.resize(count);
}

}  // namespace termshade
