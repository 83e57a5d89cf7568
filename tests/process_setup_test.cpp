// Process-wide set-up: the heap policy and the quiet start of worker threads.
#include <gtest/gtest.h>
#include <malloc.h>
#include <pthread.h>

#include <csignal>
#include <memory>
#include <thread>

#include "process/HeapPolicy.h"
#include "process/ThreadStart.h"
#include "support/SanitizerMalloc.h"

namespace termshade {
namespace {

TEST(HeapPolicy, BigArraysComeFromTheHeapNotFromMmap) {
  if (kSanitizerMalloc) GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc";
  KeepFreedMemoryForReuse();
  const size_t mappedBefore = mallinfo2().hblks;
  constexpr size_t kBytes = size_t{64} << 20;  // over glibc's largest mmap threshold
  const std::unique_ptr<char[]> big(new char[kBytes]);
  big[kBytes - 1] = 1;
  EXPECT_EQ(mallinfo2().hblks, mappedBefore);
  EXPECT_GE(mallinfo2().arena, kBytes);
}

TEST(ThreadStart, StartedThreadsTakeNoSignalsAndTheMaskComesBack) {
  sigset_t none;
  sigemptyset(&none);
  sigset_t previous;
  pthread_sigmask(SIG_SETMASK, &none, &previous);
  bool workerBlocksInt = false;
  bool workerBlocksWinch = false;
  {
    const QuietThreadStart quiet;
    std::thread worker([&] {
      sigset_t mask;
      pthread_sigmask(SIG_SETMASK, nullptr, &mask);
      workerBlocksInt = sigismember(&mask, SIGINT) == 1;
      workerBlocksWinch = sigismember(&mask, SIGWINCH) == 1;
    });
    worker.join();
  }
  sigset_t after;
  pthread_sigmask(SIG_SETMASK, &previous, &after);
  EXPECT_TRUE(workerBlocksInt);
  EXPECT_TRUE(workerBlocksWinch);
  EXPECT_EQ(sigismember(&after, SIGINT), 0);
  EXPECT_EQ(sigismember(&after, SIGWINCH), 0);
}

TEST(ThreadStart, UsableCoresIsTheAffinityMask) {
  cpu_set_t cores;
  CPU_ZERO(&cores);
  ASSERT_EQ(sched_getaffinity(0, sizeof(cores), &cores), 0);
  EXPECT_EQ(UsableCores(), CPU_COUNT(&cores));
  EXPECT_GE(UsableCores(), 1);
}

}  // namespace
}  // namespace termshade
