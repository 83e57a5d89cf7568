#include "geometry/SceneSource.h"

#include <algorithm>
#include <cstring>

namespace termshade {
namespace {

bool SameBits(Vec3 a, Vec3 b) {
  return std::memcmp(&a, &b, sizeof(Vec3)) == 0;
}

}  // namespace

void SceneSource::KeepVerticesFile(UpAxis upAxis, std::span<const Vec3> verticesWorld,
                                   std::span<const Vec3> verticesFileIn) {
  verticesFile.clear();
  inexactVertices.clear();
  inexactVerticesFile.clear();
  // A few inexact ones are listed (8 bytes more each than all of them);
  // past an eighth of the vertices, all are kept.
  const size_t most = verticesFileIn.size() / 8;
  for (size_t v = 0; v < verticesFileIn.size(); ++v) {
    if (SameBits(FileFromZUp(upAxis, verticesWorld[v] + shiftZUp), verticesFileIn[v])) continue;
    if (inexactVertices.size() == most) {
      std::vector<uint32_t>().swap(inexactVertices);
      std::vector<Vec3>().swap(inexactVerticesFile);
      verticesFile.assign(verticesFileIn.begin(), verticesFileIn.end());
      return;
    }
    inexactVertices.push_back(static_cast<uint32_t>(v));
    inexactVerticesFile.push_back(verticesFileIn[v]);
  }
}

Vec3 SceneSource::VertexFile(UpAxis upAxis, std::span<const Vec3> verticesWorld, size_t v) const {
  if (!verticesFile.empty()) return verticesFile[v];
  const auto it = std::lower_bound(inexactVertices.begin(), inexactVertices.end(), v);
  if (it != inexactVertices.end() && *it == v) {
    return inexactVerticesFile[static_cast<size_t>(it - inexactVertices.begin())];
  }
  return FileFromZUp(upAxis, verticesWorld[v] + shiftZUp);
}

}  // namespace termshade
