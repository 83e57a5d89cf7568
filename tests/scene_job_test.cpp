// SceneJob (the viewer's background builds): what a build frees goes back to
// the kernel when it ends, though the heap policy keeps freed memory otherwise.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>
#include <vector>

#include "process/HeapPolicy.h"
#include "support/SanitizerMalloc.h"
#include "tui/SceneJob.h"

namespace termshade {
namespace {

size_t ResidentBytes() {
  FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return 0;
  unsigned long pages = 0, resident = 0;  // NOLINT(google-runtime-int): fscanf's %lu
  const int read = std::fscanf(statm, "%lu %lu", &pages, &resident);
  std::fclose(statm);
  return read == 2 ? resident * static_cast<size_t>(sysconf(_SC_PAGESIZE)) : 0;
}

TEST(SceneJob, WhatABuildFreedGoesBackToTheKernelWhenItEnds) {
  if (kSanitizerMalloc) GTEST_SKIP() << "the sanitizer's allocator keeps freed memory";
  KeepFreedMemoryForReuse();
  ReturnFreedMemory();  // what earlier tests left free would be reused, not faulted in
  constexpr size_t kBlockBytes = size_t{4} << 20, kBlocks = 64;  // 256 MiB, touched, freed
  const size_t before = ResidentBytes();
  ASSERT_GT(before, 0U);
  size_t during = 0;
  SceneJob<int> job(std::make_shared<const Scene>(), [&](const Scene&, const std::atomic<bool>&) {
    std::vector<std::unique_ptr<char[]>> blocks;
    for (size_t b = 0; b < kBlocks; ++b) {
      blocks.emplace_back(new char[kBlockBytes]);
      for (size_t i = 0; i < kBlockBytes; i += 4096) blocks.back()[i] = 1;
    }
    during = ResidentBytes();
    return 0;
  });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!job.Finished() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(job.Finished());
  EXPECT_EQ(*job.Take(), 0);
  EXPECT_GE(during, before + kBlocks * kBlockBytes * 3 / 4);
  EXPECT_LT(ResidentBytes(), before + kBlocks * kBlockBytes / 4)
      << "resident before " << before << " B, during the build " << during << " B";
}

}  // namespace
}  // namespace termshade
