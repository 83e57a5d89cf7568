#include "geometry/SceneHierarchy.h"

#include "geometry/Scene.h"

namespace termshade {

std::shared_ptr<const RayBvh> SceneHierarchy::Get(const Scene& scene) const {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  if (state_->bvh == nullptr || !state_->bvh->BuiltFor(scene)) return nullptr;
  return state_->bvh;
}

void SceneHierarchy::Attach(std::shared_ptr<const RayBvh> bvh) const {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  state_->bvh = std::move(bvh);
}

}  // namespace termshade
