#include "geometry/SceneHierarchy.h"

#include "geometry/Scene.h"

namespace termshade {

const TriangleBvh* SceneHierarchy::Get(const Scene& scene) const {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  const TriangleBvh* bvh = state_->bvh.get();
  return bvh != nullptr && bvh->BuiltFor(scene) ? bvh : nullptr;
}

void SceneHierarchy::Attach(std::shared_ptr<const TriangleBvh> bvh) const {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  state_->bvh = std::move(bvh);
}

}  // namespace termshade
