#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace termshade {

struct Scene;

/// A drawable line for wire-frame mode; face is the first face that has it
/// (or UINT32_MAX for a free segment).
struct SceneEdge {
  std::array<uint32_t, 2> vertices{};
  uint32_t face = 0;
};

/// The lines of a scene: its unique undirected face edges in (low, high)
/// vertex order, each with the first face that has it, except those a face
/// hides; then the free segments.
std::vector<SceneEdge> CollectSceneEdges(const Scene& scene);

/// The lines of a prepared scene, built on first use (wire mode only needs
/// them), once, by whichever thread asks first; copies share them.
class LazySceneEdges {
 public:
  const std::vector<SceneEdge>& Get(const Scene& scene) const;

 private:
  struct State {
    std::once_flag built;
    std::vector<SceneEdge> edges;
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace termshade
