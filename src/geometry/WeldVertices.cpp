#include "geometry/WeldVertices.h"

#include <meshoptimizer.h>

#include <cstdint>
#include <vector>

#include "geometry/FirstOccurrence.h"
#include "process/HugePages.h"

namespace termshade {

void WeldExactPositions(Mesh& mesh) {
  const size_t vertexCount = mesh.verticesFile.size();
  if (vertexCount == 0) return;
  std::vector<unsigned int> remap(vertexCount);
  const size_t uniqueCount = meshopt_generateVertexRemap(
      remap.data(), nullptr, vertexCount, mesh.verticesFile.data(), vertexCount, sizeof(Vec3));
  if (uniqueCount == vertexCount) {
    bool identity = true;
    for (size_t v = 0; v < vertexCount && identity; ++v) identity = remap[v] == v;
    if (identity) return;
  }
  std::vector<Vec3> welded(uniqueCount);
  meshopt_remapVertexBuffer(welded.data(), mesh.verticesFile.data(), vertexCount, sizeof(Vec3),
                            remap.data());
  mesh.verticesFile = std::move(welded);
  for (uint32_t& corner : mesh.faceCorners) corner = remap[corner];
  for (auto& segment : mesh.segments) segment = {remap[segment[0]], remap[segment[1]]};
}

void WeldAndNumberByFirstUse(Mesh& mesh) {
  const size_t vertexCount = mesh.verticesFile.size();
  if (vertexCount == 0) return;
  // Step 1: each vertex's first vertex at the same position (bitwise).
  static_assert(sizeof(Vec3) == 24);
  std::vector<uint32_t> first(vertexCount);
  const char* positions = reinterpret_cast<const char*>(mesh.verticesFile.data());
  FindFirstOccurrences<sizeof(Vec3)>(
      vertexCount, [positions](size_t v) { return positions + v * sizeof(Vec3); }, first.data());

  // Step 2: the new number of each first vertex, by first use; every reference renumbered.
  constexpr uint32_t kUnused = UINT32_MAX;
  std::vector<uint32_t> newIndex(vertexCount, kUnused);
  uint32_t used = 0;
  const auto renumber = [&](uint32_t& v) {
    uint32_t& number = newIndex[first[v]];
    if (number == kUnused) number = used++;
    v = number;
  };
  for (uint32_t& corner : mesh.faceCorners) renumber(corner);
  for (auto& segment : mesh.segments) {
    renumber(segment[0]);
    renumber(segment[1]);
  }

  // Step 3: the vertices in their new order.
  std::vector<Vec3> reordered;
  reordered.reserve(used);
  AdviseHugePages(reordered);
  reordered.resize(used);
  for (size_t v = 0; v < vertexCount; ++v) {
    if (first[v] == v && newIndex[v] != kUnused) reordered[newIndex[v]] = mesh.verticesFile[v];
  }
  FreeAndReleasePages(mesh.verticesFile);
  mesh.verticesFile = std::move(reordered);
}

}  // namespace termshade
