#include "geometry/SceneEdges.h"

#include <algorithm>
#include <span>

#include "geometry/EdgeAdjacency.h"

namespace termshade {

std::vector<SceneEdge> CollectSceneEdges(const Mesh& mesh) {
  std::vector<SceneEdge> edges;
  EdgeAdjacency(mesh).ForEachEdge([&edges](uint32_t low, std::span<const EdgeUse> uses) {
    const bool hidden =
        std::any_of(uses.begin(), uses.end(), [](const EdgeUse& use) { return use.hidden; });
    if (!hidden) edges.push_back({{low, uses[0].highVertex}, uses[0].face});
  });
  for (const auto& segment : mesh.segments) edges.push_back({segment, UINT32_MAX});
  return edges;
}

const std::vector<SceneEdge>& LazySceneEdges::Get(const Mesh& mesh) const {
  std::call_once(state_->built, [&] { state_->edges = CollectSceneEdges(mesh); });
  return state_->edges;
}

}  // namespace termshade
