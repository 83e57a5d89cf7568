#pragma once

#include <array>
#include <cstdint>

namespace termshade {

/// The two surface passes that draw the same one-sample frame bit for bit.
enum class SurfacePass { kClusters, kHierarchy };

/// What the passes' times hold for: one hierarchy (a serial the renderer
/// bumps when it changes), one frame size, one thread count.
struct SurfaceChoiceKey {
  uint64_t hierarchySerial = 0;
  int widthSamples = 0;
  int heightSamples = 0;
  int threads = 0;
  bool operator==(const SurfaceChoiceKey&) const = default;
};

/// Chooses, frame by frame, between the cluster pass and the rays through the hierarchy
/// by their measured times: which is quicker depends on the machine (its
/// caches and memory) as much as on triangles a sample, and the frames are
/// the same either way. After a new key the first frame (cold buffers) is
/// drawn by the prior and not counted, then each pass twice in turn; then
/// the quicker (median of its last three frames; of two, the slower) is
/// drawn, and every kFirstProbeWaitFrames-th frame the other is probed, the
/// wait doubling (to kLongestProbeWaitFrames) each time the probe loses; a
/// probe quicker than that median is probed again at once, so two quick
/// frames move the choice.
class SurfacePassChoice {
 public:
  /// The pass to draw a frame of `key` by; `prior` is drawn first.
  SurfacePass Pick(const SurfaceChoiceKey& key, SurfacePass prior);
  /// The time, in ms, of the frame drawn by the pass Pick last returned.
  void Record(double timeMs);

  static constexpr int kFirstProbeWaitFrames = 8;
  static constexpr int kLongestProbeWaitFrames = 256;

 private:
  static constexpr int kKept = 3;
  struct Times {
    std::array<double, kKept> lastMs{};
    int count = 0;
    double EstimateMs() const;
  };
  Times& Of(SurfacePass pass) { return times_[pass == SurfacePass::kHierarchy ? 1 : 0]; }
  SurfacePass Quicker();

  SurfaceChoiceKey key_;
  bool started_ = false;
  bool uncounted_ = false;  ///< the frame picked is the first of its key
  SurfacePass prior_ = SurfacePass::kClusters;
  SurfacePass picked_ = SurfacePass::kClusters;
  std::array<Times, 2> times_{};
  SurfacePass best_ = SurfacePass::kClusters;
  bool probing_ = false;
  int probeWaitFrames_ = kFirstProbeWaitFrames;
  int framesToProbe_ = kFirstProbeWaitFrames;
};

}  // namespace termshade
