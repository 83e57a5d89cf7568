// Cancelling the viewer's heavy stages (issue 32, item 3): a flag set while
// PrepareScene, BuildRayBvh or BuildDetailLevels runs stops it with nothing
// half-built; RetiredJobs keeps a cancelled job until its worker ends.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "geometry/LevelOfDetail.h"
#include "geometry/RayBvh.h"
#include "geometry/Scene.h"
#include "io/scenes/SceneGenerators.h"
#include "tui/RetiredJobs.h"
#include "tui/SceneJob.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs build(cancel) with the flag set after `setAfterSeconds`; how long
// the build ran on after the flag was set (negative: it ended before).
template <typename Build>
double SecondsToStop(double setAfterSeconds, const Build& build) {
  std::atomic<bool> cancel{false};
  std::atomic<bool> ended{false};
  Clock::time_point setAt{};
  std::thread setter([&] {
    const auto at = Clock::now() + std::chrono::duration<double>(setAfterSeconds);
    while (!ended.load() && Clock::now() < at)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    setAt = Clock::now();
    cancel.store(true);
  });
  build(cancel);
  const Clock::time_point endAt = Clock::now();
  ended.store(true);
  setter.join();
  return std::chrono::duration<double>(endAt - setAt).count();
}

constexpr size_t kBigTriangles = 2000000;

TEST(Cancel, ASetFlagStopsThePreparationWithNothing) {
  std::atomic<bool> cancel{true};
  EXPECT_FALSE(PrepareScene(GenerateTriangleSphere(20000), std::nullopt, cancel).has_value());
  cancel.store(false);
  const std::optional<Scene> scene =
      PrepareScene(GenerateTriangleSphere(20000), std::nullopt, cancel);
  ASSERT_TRUE(scene.has_value());
  EXPECT_EQ(scene->triangles.size(), PrepareScene(GenerateTriangleSphere(20000)).triangles.size());
}

// The flag is set a tenth of the way into a build whose whole length was
// just measured; the build must then give nothing (the old preparation, which
// did not look, ran to its end). How soon it stops is printed, not asserted:
// timings belong to the benchmarks (docs/reliability.md has them).
TEST(Cancel, PrepareSceneFlaggedMidwayGivesNothing) {
  const Mesh mesh = GenerateTriangleSphere(kBigTriangles);
  auto start = Clock::now();
  const Scene whole = PrepareScene(mesh);
  const double wholeSeconds = SecondsSince(start);
  std::optional<Scene> cancelled;
  const double stopSeconds = SecondsToStop(wholeSeconds / 10, [&](const std::atomic<bool>& cancel) {
    cancelled = PrepareScene(mesh, std::nullopt, cancel);
  });
  std::printf("whole preparation %.3f s, stopped %.3f s after the flag\n", wholeSeconds,
              stopSeconds);
  if (stopSeconds < 0) GTEST_SKIP() << "the preparation ended before the flag was set";
  EXPECT_FALSE(cancelled.has_value());
}

// The issue's own shape: one face of millions of corners over 4 vertices,
// one triangulation call (the flag is looked at between its ears).
TEST(Cancel, PrepareSceneFlaggedInsideOneHugeFaceGivesNothing) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  constexpr uint32_t kCorners = 3000000;
  std::vector<uint32_t> corners(kCorners);
  for (uint32_t i = 0; i < kCorners; ++i) corners[i] = i % 4;
  mesh.AddFace(corners);
  auto start = Clock::now();
  const Scene whole = PrepareScene(mesh);
  const double wholeSeconds = SecondsSince(start);
  std::optional<Scene> cancelled;
  const double stopSeconds = SecondsToStop(wholeSeconds / 10, [&](const std::atomic<bool>& cancel) {
    cancelled = PrepareScene(mesh, std::nullopt, cancel);
  });
  std::printf("whole preparation %.3f s, stopped %.3f s after the flag\n", wholeSeconds,
              stopSeconds);
  if (stopSeconds < 0) GTEST_SKIP() << "the preparation ended before the flag was set";
  EXPECT_FALSE(cancelled.has_value());
}

TEST(Cancel, BuildRayBvhFlaggedMidwayGivesAnEmptyHierarchy) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(kBigTriangles));
  auto start = Clock::now();
  const RayBvh whole = BuildRayBvh(scene);
  const double wholeSeconds = SecondsSince(start);
  ASSERT_FALSE(whole.Empty());
  RayBvh cancelled;
  const double stopSeconds = SecondsToStop(wholeSeconds / 10, [&](const std::atomic<bool>& cancel) {
    cancelled = BuildRayBvh(scene, &cancel);
  });
  std::printf("whole hierarchy %.3f s, stopped %.3f s after the flag\n", wholeSeconds, stopSeconds);
  if (stopSeconds < 0) GTEST_SKIP() << "the build ended before the flag was set";
  EXPECT_TRUE(cancelled.Empty());
  EXPECT_FALSE(cancelled.BuiltFor(scene));
}

// The levels stop between steps; one meshopt_simplify call (most of the
// first level) runs to its end, so only the outcome is checked here.
TEST(Cancel, BuildDetailLevelsStoppedGivesNoLevels) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(200000));
  auto start = Clock::now();
  const DetailLevels whole = BuildDetailLevels(scene);
  const double wholeSeconds = SecondsSince(start);
  ASSERT_FALSE(whole.levels.empty());
  DetailLevels cancelled;
  const double stopSeconds = SecondsToStop(wholeSeconds / 10, [&](const std::atomic<bool>& cancel) {
    DetailBuildOptions options;
    options.cancel = &cancel;
    cancelled = BuildDetailLevels(scene, options);
  });
  std::printf("whole levels %.3f s, stopped %.3f s after the flag\n", wholeSeconds, stopSeconds);
  if (stopSeconds < 0) GTEST_SKIP() << "the build ended before the flag was set";
  EXPECT_TRUE(cancelled.levels.empty());
}

TEST(Cancel, RetiredJobsKeepsACancelledJobUntilItsWorkerEnds) {
  std::atomic<bool> release{false};
  auto job = std::make_unique<SceneJob<int>>(
      std::make_shared<const Scene>(), [&](const Scene&, const std::atomic<bool>& cancel) {
        while (!cancel.load() || !release.load())
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return 1;
      });
  RetiredJobs retired;
  retired.Keep(std::move(job));
  EXPECT_EQ(retired.Count(), 1U);
  EXPECT_TRUE(retired.Busy());  // cancelled, but its worker has not ended
  release.store(true);
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (retired.Busy() && Clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_FALSE(retired.Busy());
  EXPECT_EQ(retired.Count(), 0U);
}

}  // namespace
}  // namespace termshade
