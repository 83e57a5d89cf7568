#include "tui/MotionFrames.h"

#include <algorithm>

namespace termshade {

void MotionFrames::RoundTripMeasured(double seconds) {
  roundTripSeconds_ = seconds;
  if (minRoundTripSeconds_ == 0.0 || seconds < minRoundTripSeconds_) minRoundTripSeconds_ = seconds;
}

bool MotionFrames::LinkLimits() const {
  return roundTripSeconds_ > std::chrono::duration<double>(kSlowRoundTrip).count();
}

MotionFrames::Clock::duration MotionFrames::Rest() const {
  const auto roundTrip = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(minRoundTripSeconds_));
  return std::clamp<Clock::duration>(roundTrip, kMinRest, kMaxRest);
}

bool MotionFrames::Cheap(Clock::time_point now, bool turning) const {
  return LinkLimits() && (turning || now - movedAt_ < Rest());
}

bool MotionFrames::FullFrameDue(Clock::time_point now, bool turning) const {
  return cheapShown_ && !turning && now - movedAt_ >= Rest();
}

int MotionFrames::WakeMs(Clock::time_point now, bool turning) const {
  if (!cheapShown_ || turning) return -1;
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(movedAt_ + Rest() - now);
  return static_cast<int>(std::max<long long>(0, left.count()));
}

int CoarseLevel(int level, int levelCount, int levels) {
  if (levels < 2 || levels >= levelCount || level < 0) return level;
  const int top = levelCount - 1, steps = levels - 1;
  const int step = (level * steps * 2 + top) / (top * 2);  // nearest of the coarse levels
  return (step * top * 2 + steps) / (steps * 2);
}

}  // namespace termshade
