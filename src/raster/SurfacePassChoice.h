#pragma once

#include <array>
#include <cstdint>

namespace termshade {

/// The two surface passes that draw the same one-sample frame bit for bit.
enum class SurfacePass { kClusters, kHierarchy };

/// Chooses, frame by frame, between the cluster pass and the hierarchy walk
/// by their measured times: which is quicker depends on the machine (its
/// caches and memory) as much as on triangles a sample, and the frames are
/// the same either way. Each pass is drawn twice first; then the quicker
/// (median of its last three frames) is drawn, the other probed once after
/// 8 frames, the wait doubling (to 256) each time the probe loses; a probe
/// quicker than that median is probed again at once, so two quick frames
/// move the choice. A new scene or frame size (the key) starts again.
class SurfacePassChoice {
 public:
  /// The pass to draw a frame of `key` by; `prior` is drawn first.
  SurfacePass Pick(uint64_t key, SurfacePass prior);
  /// The time the pass Pick returned took (any unit, the same each time).
  void Record(SurfacePass pass, double time);

  static constexpr int kFirstProbeWait = 8;
  static constexpr int kLongestProbeWait = 256;

 private:
  static constexpr int kKept = 3;
  struct Times {
    std::array<double, kKept> last{};
    int count = 0;
    double Estimate() const;
  };
  Times& Of(SurfacePass pass) { return times_[pass == SurfacePass::kHierarchy ? 1 : 0]; }
  SurfacePass Quicker();

  uint64_t key_ = 0;
  bool started_ = false;
  SurfacePass prior_ = SurfacePass::kClusters;
  std::array<Times, 2> times_{};
  SurfacePass best_ = SurfacePass::kClusters;
  bool probing_ = false;
  int probeWait_ = kFirstProbeWait;
  int framesToProbe_ = kFirstProbeWait;
};

}  // namespace termshade
