// Work in a child process that a cancel stops at once (process/ChildWork.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include "process/ChildWork.h"

namespace termshade {
namespace {

TEST(ChildWork, TheChildsAnswerComesBackThroughTheSharedBytes) {
  const std::vector<int> input{3, 1, 4, 1, 5};  // the child sees this process's memory
  std::atomic<bool> cancel{false};
  int sum = 0;
  const bool answered = RunInChild(
      sizeof(int),
      [&](std::byte* shared) {
        int total = 0;
        for (const int v : input) total += v;
        std::memcpy(shared, &total, sizeof total);
      },
      [&](const std::byte* shared) { std::memcpy(&sum, shared, sizeof sum); }, cancel);
  EXPECT_TRUE(answered);
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
  const bool answered = RunInChild(
      8,
      [](std::byte*) {
        for (;;) pause();
      },
      [&](const std::byte*) { took = true; }, cancel);
  canceller.join();
  EXPECT_FALSE(answered);
  EXPECT_FALSE(took);
}

TEST(ChildWork, AChildThatDiesGivesNoAnswer) {
  std::atomic<bool> cancel{false};
  bool took = false;
  const bool answered = RunInChild(
      8, [](std::byte*) { _exit(3); }, [&](const std::byte*) { took = true; }, cancel);
  EXPECT_FALSE(answered);
  EXPECT_FALSE(took);
}

}  // namespace
}  // namespace termshade
