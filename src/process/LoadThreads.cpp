#include "process/LoadThreads.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <system_error>
#include <thread>
#include <vector>

#include "process/ThreadStart.h"

namespace termshade {

int LoadThreadCount(size_t items) {
  constexpr size_t kMinItemsPerThread = 65536;
  constexpr size_t kMostThreads = 8;
  const size_t wanted = std::min(items / kMinItemsPerThread, kMostThreads);
  if (wanted < 2) return 1;
  return std::min(UsableCores(), static_cast<int>(wanted));
}

void RunOnLoadThreads(int threads, const std::function<void(int)>& work) {
  if (threads < 1) return;
  std::vector<std::thread> started;
  if (threads > 1) {
    started.reserve(static_cast<size_t>(threads - 1));
    const QuietThreadStart quiet;
    for (int t = 1; t < threads; ++t) {
      try {
        started.emplace_back([&work, t] { work(t); });
      } catch (const std::system_error&) {
        break;  // no more threads: the calling thread does the rest
      }
    }
  }
  for (int t = static_cast<int>(started.size()) + 1; t < threads; ++t) work(t);
  work(0);
  for (std::thread& thread : started) thread.join();
}

void PopulateOnLoadThreads(void* data, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr uintptr_t kHugePage = uintptr_t{1} << 21;
  if (data == nullptr || bytes < 2 * kHugePage) return;
  const auto pageBytes = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto begin = reinterpret_cast<uintptr_t>(data);
  const uintptr_t first = (begin + pageBytes - 1) & ~(pageBytes - 1);
  const uintptr_t last = (begin + bytes) & ~(pageBytes - 1);
  if (last <= first) return;
  // Two threads from 8 MiB, a run of whole huge pages each (as far as they go).
  const int threads = LoadThreadCount((last - first) / 64);
  const auto boundary = [=](int part) {
    if (part <= 0) return first;
    if (part >= threads) return last;
    const uintptr_t at =
        first + (last - first) / static_cast<uintptr_t>(threads) * static_cast<uintptr_t>(part);
    return std::clamp(at & ~(kHugePage - 1), first, last);
  };
  RunOnLoadThreads(threads, [&boundary](int part) {
    const uintptr_t from = boundary(part), to = boundary(part + 1);
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  });
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace termshade
