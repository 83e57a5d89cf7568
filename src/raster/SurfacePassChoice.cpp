#include "raster/SurfacePassChoice.h"

#include <algorithm>
#include <limits>

namespace termshade {
namespace {

SurfacePass Other(SurfacePass pass) {
  return pass == SurfacePass::kHierarchy ? SurfacePass::kClusters : SurfacePass::kHierarchy;
}

}  // namespace

// The median of the last three; of two, the slower; of none, never quicker.
double SurfacePassChoice::Times::EstimateMs() const {
  const double a = lastMs[0], b = lastMs[1], c = lastMs[2];
  if (count >= kKept) return std::max(std::min(a, b), std::min(std::max(a, b), c));
  if (count == 2) return std::max(a, b);
  return count == 1 ? a : std::numeric_limits<double>::infinity();
}

SurfacePass SurfacePassChoice::Quicker() {
  const double hierarchy = Of(SurfacePass::kHierarchy).EstimateMs();
  const double clusters = Of(SurfacePass::kClusters).EstimateMs();
  if (hierarchy == clusters) return prior_;
  return hierarchy < clusters ? SurfacePass::kHierarchy : SurfacePass::kClusters;
}

SurfacePass SurfacePassChoice::Pick(const SurfaceChoiceKey& key, SurfacePass prior) {
  probing_ = false;
  uncounted_ = false;
  if (!started_ || !(key == key_)) {
    *this = SurfacePassChoice{};
    started_ = true;
    key_ = key;
    prior_ = prior;
    uncounted_ = true;
    return picked_ = prior_;
  }
  // Step 1: each pass twice, taking turns from the prior.
  const Times& first = Of(prior_);
  const Times& second = Of(Other(prior_));
  if (second.count < 2) return picked_ = first.count <= second.count ? prior_ : Other(prior_);
  // Step 2: the quicker, with the other probed now and then.
  if (--framesToProbe_ > 0) return picked_ = best_;
  probing_ = true;
  return picked_ = Other(best_);
}

void SurfacePassChoice::Record(double timeMs) {
  if (!started_ || uncounted_) return;
  Times& times = Of(picked_);
  times.lastMs[static_cast<size_t>(times.count % kKept)] = timeMs;
  ++times.count;
  const SurfacePass before = best_;
  best_ = Quicker();
  if (!probing_) return;
  if (best_ != before) {  // the probe won: probe the loser soon
    probeWaitFrames_ = kFirstProbeWaitFrames;
    framesToProbe_ = probeWaitFrames_;
  } else if (timeMs < Of(best_).EstimateMs()) {  // one quicker frame: probe again next frame
    framesToProbe_ = 1;
  } else {  // it lost: wait longer next time
    probeWaitFrames_ = std::min(2 * probeWaitFrames_, kLongestProbeWaitFrames);
    framesToProbe_ = probeWaitFrames_;
  }
}

}  // namespace termshade
