#include "geometry/SceneEdges.h"

#include <algorithm>
#include <span>

#include "geometry/EdgeAdjacency.h"
#include "geometry/Scene.h"

namespace termshade {

std::vector<SceneEdge> CollectSceneEdges(const Scene& scene) {
  std::vector<SceneEdge> edges;
  EdgeAdjacency(scene.verticesWorld.size(), scene)
      .ForEachEdge([&edges](uint32_t low, std::span<const EdgeUse> uses) {
        const bool hidden =
            std::any_of(uses.begin(), uses.end(), [](const EdgeUse& use) { return use.Hidden(); });
        if (!hidden) edges.push_back({{low, uses[0].highVertex}, uses[0].Face()});
      });
  for (const auto& segment : scene.source.segments) edges.push_back({segment, UINT32_MAX});
  return edges;
}

const std::vector<SceneEdge>& LazySceneEdges::Get(const Scene& scene) const {
  std::call_once(state_->built, [&] { state_->edges = CollectSceneEdges(scene); });
  return state_->edges;
}

}  // namespace termshade
