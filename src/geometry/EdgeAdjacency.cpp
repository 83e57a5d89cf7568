#include "geometry/EdgeAdjacency.h"

#include <algorithm>

#include "geometry/HugePages.h"

namespace termshade {

EdgeAdjacency::EdgeAdjacency(const Mesh& mesh) {
  const size_t vertexCount = mesh.verticesFile.size();
  // Step 1: how many edges start at each smaller vertex.
  starts_.reserve(vertexCount + 1);
  AdviseHugePages(starts_);
  starts_.assign(vertexCount + 1, 0);
  auto forEachFaceEdge = [&mesh](auto&& use) {
    for (uint32_t face = 0; face < mesh.FaceCount(); ++face) {
      const auto corners = mesh.Face(face);
      for (size_t i = 0; i < corners.size(); ++i) {
        const uint32_t a = corners[i], b = corners[(i + 1) % corners.size()];
        if (a != b) use(a, b, face, mesh.edgeHidden[mesh.faceStarts[face] + i] != 0);
      }
    }
  };
  forEachFaceEdge([&](uint32_t a, uint32_t b, uint32_t, bool) { ++starts_[std::min(a, b) + 1]; });
  for (size_t v = 0; v < vertexCount; ++v) starts_[v + 1] += starts_[v];

  // Step 2: place each use in its vertex's range.
  uses_.reserve(starts_.back());
  AdviseHugePages(uses_);
  uses_.resize(starts_.back());
  std::vector<uint32_t> filled(starts_.begin(), starts_.end() - 1);
  forEachFaceEdge([&](uint32_t a, uint32_t b, uint32_t face, bool hidden) {
    uses_[filled[std::min(a, b)]++] = {std::max(a, b), face, a < b, hidden};
  });

  // Step 3: within a vertex, by larger vertex, then face.
  for (size_t v = 0; v < vertexCount; ++v) {
    std::sort(uses_.begin() + starts_[v], uses_.begin() + starts_[v + 1],
              [](const EdgeUse& p, const EdgeUse& q) {
                return p.highVertex != q.highVertex ? p.highVertex < q.highVertex : p.face < q.face;
              });
  }
}

}  // namespace termshade
