#include "geometry/WeldVertices.h"

#include <meshoptimizer.h>

#include <vector>

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

}  // namespace termshade
