// The renderer's choice between the cluster pass and the hierarchy walk by
// their measured times (SurfacePassChoice), driven here by given times.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "raster/SurfacePassChoice.h"

namespace termshade {
namespace {

constexpr SurfacePass kC = SurfacePass::kClusters;
constexpr SurfacePass kH = SurfacePass::kHierarchy;

// The passes picked over `frames` frames of one key, each taking the time `timeOf` gives.
template <typename TimeOf>
std::vector<SurfacePass> RunFrames(SurfacePassChoice& choice, uint64_t serial, SurfacePass prior,
                                   int frames, TimeOf timeOf) {
  std::vector<SurfacePass> picked;
  const SurfaceChoiceKey key{serial, 160, 48, 2};
  for (int frame = 0; frame < frames; ++frame) {
    const SurfacePass pass = choice.Pick(key, prior);
    choice.Record(timeOf(pass, frame));
    picked.push_back(pass);
  }
  return picked;
}

std::vector<int> FramesOf(const std::vector<SurfacePass>& picked, SurfacePass pass) {
  std::vector<int> frames;
  for (size_t i = 0; i < picked.size(); ++i) {
    if (picked[i] == pass) frames.push_back(static_cast<int>(i));
  }
  return frames;
}

auto Constant(double clusters, double hierarchy) {
  return [=](SurfacePass pass, int) { return pass == kC ? clusters : hierarchy; };
}

TEST(SurfacePassChoice, TriesBothInTurnFromThePrior) {
  SurfacePassChoice choice;
  const auto picked = RunFrames(choice, 1, kH, 5, Constant(1.0, 2.0));
  // The first frame of a key (cold) is the prior's and not counted.
  EXPECT_EQ(picked, (std::vector<SurfacePass>{kH, kH, kC, kH, kC}));
}

// The quicker is kept; the slower is probed after 8 frames, then 16, 32, ...
// up to 256 while it keeps losing.
TEST(SurfacePassChoice, KeepsTheQuickerAndProbesTheOtherEverLessOften) {
  SurfacePassChoice choice;
  const auto picked =
      RunFrames(choice, 1, kH, 5 + 8 + 16 + 32 + 64 + 128 + 256 + 256, Constant(1.0, 2.0));
  std::vector<int> expected{0, 1, 3};
  int at = 4;
  for (int wait = 8; wait <= 256; wait *= 2) expected.push_back(at += wait);
  expected.push_back(at + 256);  // the longest wait again
  EXPECT_EQ(FramesOf(picked, kH), expected);
}

// The walk turns quicker (the model grew on screen, say): the probe finds it
// and the choice moves to it, probing the clusters back after 8 frames.
TEST(SurfacePassChoice, FollowsThePassThatBecomesQuicker) {
  SurfacePassChoice choice;
  auto timeOf = [](SurfacePass pass, int frame) {
    if (pass == kC) return 1.0;
    return frame < 20 ? 2.0 : 0.5;
  };
  const auto picked = RunFrames(choice, 1, kC, 61, timeOf);
  EXPECT_EQ(picked[12], kH);  // the first probe: 2.0, slower
  EXPECT_EQ(picked[13], kC);
  EXPECT_EQ(picked[28], kH);  // the second, 16 frames on: 0.5, quicker than clusters' 1.0 ...
  EXPECT_EQ(picked[29], kH);  // ... so probed again at once, and the walk is taken
  std::vector<int> clustersAfter;
  for (const int frame : FramesOf(picked, kC)) {
    if (frame > 29) clustersAfter.push_back(frame);
  }
  EXPECT_EQ(clustersAfter, (std::vector<int>{37, 53}));  // probes 8, then 16 frames apart
}

// One slow frame (another program took the core) does not move the choice,
// nor does a slow first frame of a key.
TEST(SurfacePassChoice, OneSlowFrameDoesNotSwitch) {
  SurfacePassChoice choice;
  auto timeOf = [](SurfacePass pass, int frame) {
    if (pass == kH) return 2.0;
    return frame == 0 || frame == 7 ? 50.0 : 1.0;
  };
  const auto picked = RunFrames(choice, 1, kC, 12, timeOf);
  EXPECT_EQ(FramesOf(picked, kH), (std::vector<int>{2, 4}));
}

// Two times of a pass count as the slower of them: one quick frame of the
// walk does not beat the clusters until it is seen again.
TEST(SurfacePassChoice, OfTwoTimesTheSlowerCounts) {
  SurfacePassChoice choice;
  auto timeOf = [](SurfacePass pass, int frame) {
    if (pass == kC) return 1.0;
    return frame == 2 ? 0.5 : 3.0;
  };
  const auto picked = RunFrames(choice, 1, kC, 7, timeOf);
  EXPECT_EQ(FramesOf(picked, kH), (std::vector<int>{2, 4}));
}

// Another hierarchy, frame size or thread count (another key) starts over from its prior.
TEST(SurfacePassChoice, ANewKeyStartsOver) {
  SurfacePassChoice choice;
  RunFrames(choice, 1, kH, 30, Constant(1.0, 2.0));
  EXPECT_EQ(RunFrames(choice, 2, kH, 5, Constant(1.0, 2.0)),
            (std::vector<SurfacePass>{kH, kH, kC, kH, kC}));
  RunFrames(choice, 2, kH, 30, Constant(1.0, 2.0));
  EXPECT_EQ(choice.Pick({2, 80, 24, 2}, kC), kC);  // another size: the prior, uncounted
  choice.Record(9.0);
  EXPECT_EQ(choice.Pick({2, 80, 24, 2}, kC), kC);
  choice.Record(1.0);
  EXPECT_EQ(choice.Pick({2, 80, 24, 2}, kC), kH);
}

}  // namespace
}  // namespace termshade
