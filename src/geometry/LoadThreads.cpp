#include "geometry/LoadThreads.h"

#include <pthread.h>
#include <sched.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <csignal>
#include <system_error>
#include <thread>
#include <vector>

namespace termshade {

int LoadThreadCount(size_t items) {
  constexpr size_t kMinItemsPerThread = 65536;
  constexpr size_t kMostThreads = 8;
  const size_t wanted = std::min(items / kMinItemsPerThread, kMostThreads);
  if (wanted < 2) return 1;
  // The cores this process may run on, by a system call: hardware_concurrency
  // reads /sys, a file outside the model's folder (tests/models/corpus_check.sh).
  cpu_set_t cores;
  CPU_ZERO(&cores);
  if (sched_getaffinity(0, sizeof(cores), &cores) != 0) return 1;
  return static_cast<int>(std::clamp<size_t>(static_cast<size_t>(CPU_COUNT(&cores)), 1, wanted));
}

void RunOnLoadThreads(int threads, const std::function<void(int)>& work) {
  if (threads < 1) return;
  std::vector<std::thread> started;
  if (threads > 1) {
    started.reserve(static_cast<size_t>(threads - 1));
#if defined(__GLIBC__)
    // One malloc arena for every thread, as the frame's WorkerPool sets: a
    // thread's own arena, once it shrinks, makes glibc read a file outside
    // the model's folder (/proc/sys/vm/overcommit_memory).
    mallopt(M_ARENA_MAX, 1);
#endif
    sigset_t all, previous;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &previous);
    for (int t = 1; t < threads; ++t) {
      try {
        started.emplace_back([&work, t] { work(t); });
      } catch (const std::system_error&) {
        break;  // no more threads: the calling thread does the rest
      }
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  }
  for (int t = static_cast<int>(started.size()) + 1; t < threads; ++t) work(t);
  work(0);
  for (std::thread& thread : started) thread.join();
}

}  // namespace termshade
