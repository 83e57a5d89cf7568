#include "tui/MotionFrames.h"

#include <gtest/gtest.h>

namespace termshade {
namespace {

using Clock = MotionFrames::Clock;
using std::chrono::milliseconds;

TEST(MotionFrames, FullFramesWhileTheTerminalKeepsUp) {
  MotionFrames motion;
  const Clock::time_point t0{};
  motion.RoundTripMeasured(0.002);  // a local terminal
  motion.ViewMoved(t0);
  EXPECT_FALSE(motion.LinkLimits());
  EXPECT_FALSE(motion.Cheap(t0, false));
  EXPECT_FALSE(motion.Cheap(t0, true));
}

TEST(MotionFrames, CheapWhileMovingOnASlowLinkThenTheFullFrameOneRoundTripAfter) {
  MotionFrames motion;
  const Clock::time_point t0{};
  motion.RoundTripMeasured(0.2);
  EXPECT_TRUE(motion.LinkLimits());
  EXPECT_FALSE(motion.Cheap(t0 + milliseconds(1000), false));  // at rest: full frames
  motion.ViewMoved(t0);
  EXPECT_TRUE(motion.Cheap(t0 + milliseconds(10), false));
  motion.FrameDrawn(true);
  EXPECT_FALSE(motion.FullFrameDue(t0 + milliseconds(150), false));
  EXPECT_EQ(motion.WakeMs(t0 + milliseconds(150), false), 50);
  EXPECT_TRUE(motion.FullFrameDue(t0 + milliseconds(200), false));
  EXPECT_FALSE(motion.Cheap(t0 + milliseconds(200), false));
  motion.FrameDrawn(false);
  EXPECT_FALSE(motion.FullFrameDue(t0 + milliseconds(300), false));
  EXPECT_EQ(motion.WakeMs(t0 + milliseconds(300), false), -1);
}

TEST(MotionFrames, TheTurntableStaysCheapUntilItStops) {
  MotionFrames motion;
  const Clock::time_point t0{};
  motion.RoundTripMeasured(0.6);
  motion.ViewMoved(t0);
  motion.FrameDrawn(true);
  EXPECT_TRUE(motion.Cheap(t0 + milliseconds(5000), true));
  EXPECT_FALSE(motion.FullFrameDue(t0 + milliseconds(5000), true));
  EXPECT_EQ(motion.WakeMs(t0 + milliseconds(5000), true), -1);
  // The rest waits one round trip, at most kMaxRest.
  EXPECT_TRUE(motion.FullFrameDue(t0 + MotionFrames::kMaxRest, false));
}

TEST(MotionFrames, CoarseLevelsKeepTheEndsAndOrder) {
  EXPECT_EQ(CoarseLevel(0, 9, 3), 0);
  EXPECT_EQ(CoarseLevel(8, 9, 3), 8);
  EXPECT_EQ(CoarseLevel(4, 9, 3), 4);
  EXPECT_EQ(CoarseLevel(1, 9, 3), 0);
  EXPECT_EQ(CoarseLevel(7, 9, 3), 8);
  EXPECT_EQ(CoarseLevel(-1, 9, 3), -1);  // no face
  EXPECT_EQ(CoarseLevel(5, 9, 0), 5);    // full frames
  EXPECT_EQ(CoarseLevel(2, 3, 3), 2);
  for (int levels = 2; levels <= 8; ++levels) {
    int last = 0;
    for (int level = 0; level < 64; ++level) {
      const int coarse = CoarseLevel(level, 64, levels);
      EXPECT_GE(coarse, last);
      EXPECT_LT(coarse, 64);
      last = coarse;
    }
  }
}

}  // namespace
}  // namespace termshade
