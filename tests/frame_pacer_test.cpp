#include "tui/FramePacer.h"

#include <gtest/gtest.h>

namespace termshade {
namespace {

using Clock = FramePacer::Clock;
using std::chrono::milliseconds;

TEST(FramePacer, OneFrameInFlightUntilItsAnswer) {
  FramePacer pacer;
  const Clock::time_point t0{};
  EXPECT_TRUE(pacer.MayDraw(t0));
  EXPECT_EQ(pacer.WakeMs(t0), -1);
  pacer.RequestSent(t0, 17000);
  EXPECT_FALSE(pacer.MayDraw(t0 + milliseconds(300)));
  EXPECT_EQ(pacer.BytesInFlight(), 17000U);
  EXPECT_EQ(pacer.WakeMs(t0 + milliseconds(300)), 700);  // the first answer's timeout
  pacer.AnswerRead(t0 + milliseconds(400));
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(400)));
  EXPECT_DOUBLE_EQ(pacer.LastRoundTripSeconds(), 0.4);
  EXPECT_EQ(pacer.RequestsInFlight(), 0U);
  EXPECT_TRUE(pacer.Answering());
}

TEST(FramePacer, AnswersComeInOrderOnePerRequest) {
  FramePacer pacer;
  const Clock::time_point t0{};
  pacer.RequestSent(t0, 0);  // the probe before the first frame
  pacer.RequestSent(t0, 25000);
  pacer.AnswerRead(t0 + milliseconds(100));
  EXPECT_FALSE(pacer.MayDraw(t0 + milliseconds(100)));  // the frame is still on its way
  pacer.AnswerRead(t0 + milliseconds(900));
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(900)));
}

TEST(FramePacer, SmallFramesMayShareTheBudget) {
  FramePacer pacer;
  const Clock::time_point t0{};
  pacer.RequestSent(t0, 0);  // the probe: the first frame need not wait for it
  EXPECT_TRUE(pacer.MayDraw(t0));
  pacer.RequestSent(t0, 1500);
  EXPECT_TRUE(pacer.MayDraw(t0));
  pacer.RequestSent(t0, 1500);
  EXPECT_TRUE(pacer.MayDraw(t0));
  pacer.RequestSent(t0, 1500);  // 4500 bytes in flight: past the budget
  EXPECT_FALSE(pacer.MayDraw(t0));
  pacer.AnswerRead(t0 + milliseconds(100));  // the probe's
  EXPECT_FALSE(pacer.MayDraw(t0 + milliseconds(100)));
  pacer.AnswerRead(t0 + milliseconds(150));
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(150)));
}

TEST(FramePacer, ATerminalThatNeverAnswersIsPacedWithoutAnswers) {
  FramePacer pacer;
  const Clock::time_point t0{};
  pacer.RequestSent(t0, 5000);
  EXPECT_FALSE(pacer.MayDraw(t0 + milliseconds(999)));
  EXPECT_TRUE(pacer.MayDraw(t0 + FramePacer::kFirstAnswerTimeout));
  EXPECT_FALSE(pacer.Answering());
  pacer.RequestSent(t0 + milliseconds(1000), 5000);
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(1001)));
  EXPECT_EQ(pacer.WakeMs(t0 + milliseconds(1001)), -1);
}

TEST(FramePacer, ALateAnswerTurnsAnswersBackOn) {
  FramePacer pacer;
  const Clock::time_point t0{};
  pacer.RequestSent(t0, 5000);
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(1500)));  // given up on
  pacer.RequestSent(t0 + milliseconds(1500), 5000);
  pacer.AnswerRead(t0 + milliseconds(1600));  // the first request's, late
  EXPECT_TRUE(pacer.Answering());
  EXPECT_FALSE(pacer.MayDraw(t0 + milliseconds(1600)));  // the second is in flight
  pacer.AnswerRead(t0 + milliseconds(1700));
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(1700)));
  // An answer with nothing in flight (one given up on, answered very late): no harm.
  pacer.AnswerRead(t0 + milliseconds(1800));
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(1800)));
}

TEST(FramePacer, OnceAnsweredASlowFrameIsWaitedForLonger) {
  FramePacer pacer;
  const Clock::time_point t0{};
  pacer.RequestSent(t0, 0);
  pacer.AnswerRead(t0 + milliseconds(50));
  pacer.RequestSent(t0 + milliseconds(50), 60000);  // 2 s at 256 kbit/s
  EXPECT_FALSE(pacer.MayDraw(t0 + milliseconds(2500)));
  EXPECT_TRUE(pacer.Answering());
  EXPECT_TRUE(pacer.MayDraw(t0 + milliseconds(50) + FramePacer::kAnswerTimeout));
  EXPECT_FALSE(pacer.Answering());
}

}  // namespace
}  // namespace termshade
