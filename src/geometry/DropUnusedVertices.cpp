#include "geometry/DropUnusedVertices.h"

#include <vector>

namespace termshade {

void DropUnusedVertices(Mesh& mesh) {
  constexpr uint32_t kUnused = UINT32_MAX;
  std::vector<uint32_t> newIndex(mesh.verticesFile.size(), kUnused);
  for (const uint32_t corner : mesh.faceCorners) newIndex[corner] = 0;
  for (const auto& segment : mesh.segments) newIndex[segment[0]] = newIndex[segment[1]] = 0;
  uint32_t kept = 0;
  for (size_t v = 0; v < newIndex.size(); ++v) {
    if (newIndex[v] == kUnused) continue;
    newIndex[v] = kept;
    mesh.verticesFile[kept++] = mesh.verticesFile[v];
  }
  if (kept == mesh.verticesFile.size()) return;
  mesh.verticesFile.resize(kept);
  for (uint32_t& corner : mesh.faceCorners) corner = newIndex[corner];
  for (auto& segment : mesh.segments) segment = {newIndex[segment[0]], newIndex[segment[1]]};
}

}  // namespace termshade
