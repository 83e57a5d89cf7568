#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <thread>

#include "raster/WorkerPool.h"

namespace termshade {
namespace {

using std::chrono::milliseconds;

// Each Run calls every worker once, and what the workers wrote is visible to
// the caller when Run returns (plain writes, no atomics).
void ExpectEveryWorkerOnce(WorkerPool& pool, int runs, milliseconds pauseBetween) {
  std::array<int, 4> calls{};
  for (int run = 0; run < runs; ++run) {
    auto job = [&](int worker) { ++calls[static_cast<size_t>(worker)]; };
    pool.Run(job);
    for (int w = 0; w < pool.Workers(); ++w) ASSERT_EQ(calls[static_cast<size_t>(w)], run + 1);
    if (pauseBetween.count() > 0) std::this_thread::sleep_for(pauseBetween);
  }
}

TEST(WorkerPool, BackToBackJobsRunOnEveryWorkerOnce) {
  WorkerPool pool(3);
  ExpectEveryWorkerOnce(pool, 3000, milliseconds(0));
}

TEST(WorkerPool, JobsReachWorkersThatHaveGoneToSleep) {
  WorkerPool pool(3);
  // Longer than the spin: the workers block between jobs.
  ExpectEveryWorkerOnce(pool, 40, milliseconds(3));
}

TEST(WorkerPool, RunWaitsForASlowWorker) {
  WorkerPool pool(2);
  for (int run = 0; run < 5; ++run) {
    bool slowDone = false;
    auto job = [&](int worker) {
      if (worker == 1) {
        std::this_thread::sleep_for(milliseconds(5));  // past the caller's spin
        slowDone = true;
      }
    };
    pool.Run(job);
    EXPECT_TRUE(slowDone);
  }
}

TEST(WorkerPool, StopsWhetherItsWorkersSpinOrSleep) {
  for (int pause : {0, 5}) {
    WorkerPool pool(3);
    auto job = [](int) {};
    pool.Run(job);
    std::this_thread::sleep_for(milliseconds(pause));
  }  // a lost wake-up hangs here (the test's timeout)
  SUCCEED();
}

}  // namespace
}  // namespace termshade
