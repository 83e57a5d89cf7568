#pragma once

#include <memory>
#include <mutex>

#include "geometry/RayBvh.h"

namespace termshade {

struct Scene;

/// The triangle hierarchy of a prepared scene (RayBvh, for RayCastStage),
/// attached once built (on a worker, for big scenes drawn many times);
/// copies share it. Get checks that it was built for this scene's triangles.
class SceneHierarchy {
 public:
  /// The hierarchy, or null when none is attached or it is another scene's
  /// (shared: a later Attach does not free it under a frame that reads it).
  std::shared_ptr<const RayBvh> Get(const Scene& scene) const;
  void Attach(std::shared_ptr<const RayBvh> bvh) const;

 private:
  struct State {
    std::mutex mutex;
    std::shared_ptr<const RayBvh> bvh;
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace termshade
