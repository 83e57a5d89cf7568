#include "geometry/LoadThreads.h"

#include <algorithm>
#include <system_error>
#include <thread>
#include <vector>

#include "geometry/ThreadStart.h"

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

}  // namespace termshade
