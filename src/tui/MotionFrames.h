#pragma once

#include <chrono>

namespace termshade {

/// Cheaper frames while the view moves on a slow link (issue 31). When the
/// terminal's answers come back slower than a frame period (the link, not the
/// viewer, caps the frame rate), frames drawn while the view moves (keys,
/// mouse, the turntable) use a cheaper colour encoding: the 256-colour
/// palette and kMotionLevels shades, so SGR runs are longer and fewer cells
/// change from frame to frame. Once the view has rested for a round trip the
/// full frame follows. Only the screen ever gets a cheap frame: dumps,
/// `render` and recordings draw full frames. No clock is read here: every
/// call is told the time, so tests drive it.
class MotionFrames {
 public:
  using Clock = std::chrono::steady_clock;

  /// Shades a cheap frame keeps of the ramp's levels (darkest and brightest among them).
  static constexpr int kMotionLevels = 3;
  /// A round trip longer than a frame period: frames wait for the link.
  static constexpr std::chrono::milliseconds kSlowRoundTrip{40};
  /// The rest that brings the full frame: one round trip (the shortest
  /// measured, the link's delay without frames queued), within these bounds.
  static constexpr std::chrono::milliseconds kMinRest{40};
  static constexpr std::chrono::milliseconds kMaxRest{500};

  /// The terminal answered for a frame after `seconds` (FramePacer's last round trip).
  void RoundTripMeasured(double seconds);
  /// Keys, the mouse or the turntable changed what is shown at `now`.
  void ViewMoved(Clock::time_point now) { movedAt_ = now; }
  /// Whether the link limits the frame rate (the last round trip was slow).
  bool LinkLimits() const;
  /// Whether a frame drawn at `now` may be cheap: the link limits, and the
  /// view turns or moved within the rest time.
  bool Cheap(Clock::time_point now, bool turning) const;
  /// A frame went out, cheap or not.
  void FrameDrawn(bool cheap) { cheapShown_ = cheap; }
  /// A cheap frame is on the screen and the view has rested: the full frame is due.
  bool FullFrameDue(Clock::time_point now, bool turning) const;
  /// Milliseconds until FullFrameDue may turn true, or -1.
  int WakeMs(Clock::time_point now, bool turning) const;

 private:
  Clock::duration Rest() const;

  double roundTripSeconds_ = 0.0;     ///< the last
  double minRoundTripSeconds_ = 0.0;  ///< the shortest yet: the link's own delay
  Clock::time_point movedAt_;
  bool cheapShown_ = false;
};

/// A shade level of `levelCount` moved to the nearest of `levels` levels
/// spread evenly from the darkest to the brightest (itself for levels < 2
/// or no fewer levels than the ramp has).
int CoarseLevel(int level, int levelCount, int levels);

}  // namespace termshade
