#include "io/load/ExtrasBudget.h"

#include <algorithm>

#include "io/read/LoadBudget.h"
#include "io/read/RegularFile.h"

namespace termshade {

size_t EstimateSceneBytes(const Scene& scene) {
  const size_t faces = scene.facePlanesWorld.size();
  const size_t corners = std::max(scene.source.faces.corners.size(), 3 * scene.triangles.size());
  return EstimatePreparedBytes(0, scene.verticesWorld.size(), corners, faces) +
         scene.textures.HeldBytes();
}

std::optional<std::string> ExtraOverBudget(std::string_view what, size_t extraBytes,
                                           const Scene& scene, size_t heldBytes,
                                           size_t budgetBytes) {
  const size_t sceneBytes = EstimateSceneBytes(scene) + heldBytes;
  if (sceneBytes + extraBytes <= budgetBytes) return std::nullopt;
  return std::string(what) + " skipped: it needs about " +
         FormatBytes(static_cast<double>(extraBytes)) + " beside the model's " +
         FormatBytes(static_cast<double>(sceneBytes)) + ", more than the memory budget of " +
         FormatBytes(static_cast<double>(budgetBytes)) + " (--memory-budget)";
}

}  // namespace termshade
