#include "geometry/FirstUseOrder.h"

#include <cstdint>
#include <vector>

namespace termshade {

void NumberVerticesByFirstUse(Mesh& mesh) {
  const size_t vertexCount = mesh.verticesFile.size();
  if (vertexCount == 0) return;
  // Step 1: the new number of each vertex, by first use (kUnused: none).
  constexpr uint32_t kUnused = UINT32_MAX;
  std::vector<uint32_t> newIndex(vertexCount, kUnused);
  uint32_t used = 0;
  const auto number = [&](uint32_t v) {
    if (newIndex[v] == kUnused) newIndex[v] = used++;
  };
  for (const uint32_t corner : mesh.faceCorners) number(corner);
  for (const auto& segment : mesh.segments) {
    number(segment[0]);
    number(segment[1]);
  }
  bool identity = used == vertexCount;
  for (size_t v = 0; v < vertexCount && identity; ++v) identity = newIndex[v] == v;
  if (identity) return;
  // Step 2: the vertices in their new order, and every reference renumbered.
  std::vector<Vec3> reordered(used);
  for (size_t v = 0; v < vertexCount; ++v) {
    if (newIndex[v] != kUnused) reordered[newIndex[v]] = mesh.verticesFile[v];
  }
  mesh.verticesFile = std::move(reordered);
  for (uint32_t& corner : mesh.faceCorners) corner = newIndex[corner];
  for (auto& segment : mesh.segments) segment = {newIndex[segment[0]], newIndex[segment[1]]};
}

}  // namespace termshade
