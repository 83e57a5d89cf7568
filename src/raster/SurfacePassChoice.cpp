#include "raster/SurfacePassChoice.h"

#include <algorithm>

namespace termshade {
namespace {

SurfacePass Other(SurfacePass pass) {
  return pass == SurfacePass::kHierarchy ? SurfacePass::kClusters : SurfacePass::kHierarchy;
}

}  // namespace

// The median of the last three; of two, the slower; none: 0.
double SurfacePassChoice::Times::Estimate() const {
  const double a = last[0], b = last[1], c = last[2];
  if (count >= kKept) return std::max(std::min(a, b), std::min(std::max(a, b), c));
  return count == 2 ? std::max(a, b) : a;
}

SurfacePass SurfacePassChoice::Quicker() {
  const double hierarchy = Of(SurfacePass::kHierarchy).Estimate();
  const double clusters = Of(SurfacePass::kClusters).Estimate();
  if (hierarchy == clusters) return prior_;
  return hierarchy < clusters ? SurfacePass::kHierarchy : SurfacePass::kClusters;
}

SurfacePass SurfacePassChoice::Pick(uint64_t key, SurfacePass prior) {
  if (!started_ || key != key_) {
    *this = SurfacePassChoice{};
    started_ = true;
    key_ = key;
    prior_ = prior;
  }
  probing_ = false;
  // Step 1: each pass twice, taking turns from the prior.
  const Times& first = Of(prior_);
  const Times& second = Of(Other(prior_));
  if (second.count < 2) return first.count <= second.count ? prior_ : Other(prior_);
  // Step 2: the quicker, with the other probed now and then.
  if (--framesToProbe_ > 0) return best_;
  probing_ = true;
  return Other(best_);
}

void SurfacePassChoice::Record(SurfacePass pass, double time) {
  Times& times = Of(pass);
  times.last[static_cast<size_t>(times.count % kKept)] = time;
  ++times.count;
  if (Of(Other(prior_)).count < 2) {
    best_ = Quicker();
    return;
  }
  const SurfacePass before = best_;
  best_ = Quicker();
  if (!probing_) return;
  if (best_ != before) {  // the probe won: probe the loser soon
    probeWait_ = kFirstProbeWait;
    framesToProbe_ = probeWait_;
  } else if (time < Of(best_).Estimate()) {  // one quicker frame: probe again next frame
    framesToProbe_ = 1;
  } else {  // it lost: wait longer next time
    probeWait_ = std::min(2 * probeWait_, kLongestProbeWait);
    framesToProbe_ = probeWait_;
  }
}

}  // namespace termshade
