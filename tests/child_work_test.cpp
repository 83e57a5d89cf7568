// Work in a child process that a cancel stops at once (process/ChildWork.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

#include "process/ChildWork.h"

namespace termshade {
namespace {

TEST(ChildWork, TheChildsAnswerComesBackThroughTheSharedBytes) {
  const std::vector<int> input{3, 1, 4, 1, 5};  // the child sees this process's memory
  std::atomic<bool> cancel{false};
  int sum = 0;
  const ChildOutcome outcome = RunInChild(
      sizeof(int),
      [&](std::byte* shared) {
        int total = 0;
        for (const int v : input) total += v;
        std::memcpy(shared, &total, sizeof total);
      },
      [&](const std::byte* shared) { std::memcpy(&sum, shared, sizeof sum); }, cancel);
  EXPECT_EQ(outcome, ChildOutcome::kAnswered);
  EXPECT_EQ(sum, 14);
}

TEST(ChildWork, ACancelStopsWorkThatWouldNeverEnd) {
  std::atomic<bool> cancel{false};
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    cancel.store(true);
  });
  bool took = false;
  // Without the cancel this never returns (the test would time out).
  const ChildOutcome outcome = RunInChild(
      8,
      [](std::byte*) {
        for (;;) pause();
      },
      [&](const std::byte*) { took = true; }, cancel);
  canceller.join();
  EXPECT_EQ(outcome, ChildOutcome::kCancelled);
  EXPECT_FALSE(took);
}

TEST(ChildWork, AChildThatDiesGivesNoAnswer) {
  std::atomic<bool> cancel{false};
  bool took = false;
  EXPECT_EQ(RunInChild(
                8, [](std::byte*) { _exit(3); }, [&](const std::byte*) { took = true; }, cancel),
            ChildOutcome::kDied);
  // An exception, or a crash with this process's handlers armed: the child
  // ends quietly (default dispositions, no descriptors), this process goes on.
  EXPECT_EQ(RunInChild(
                8, [](std::byte*) { throw std::runtime_error("no"); },
                [&](const std::byte*) { took = true; }, cancel),
            ChildOutcome::kDied);
  struct sigaction previous {};
  struct sigaction loud {};
  loud.sa_handler = [](int) {
    const char text[] = "handler ran in the child\n";
    (void)!write(STDERR_FILENO, text, sizeof text - 1);
  };
  sigaction(SIGUSR1, &loud, &previous);
  EXPECT_EQ(
      RunInChild(
          8, [](std::byte*) { raise(SIGUSR1); }, [&](const std::byte*) { took = true; }, cancel),
      ChildOutcome::kDied);  // SIGUSR1's default ends it, the handler is gone
  sigaction(SIGUSR1, &previous, nullptr);
  EXPECT_FALSE(took);
}

}  // namespace
}  // namespace termshade
