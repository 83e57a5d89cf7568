#include "geometry/OutwardOrientation.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace termshade {
namespace {

// Union-find over faces, with path halving.
class FaceParts {
 public:
  explicit FaceParts(size_t faceCount) : parent_(faceCount) {
    for (size_t f = 0; f < faceCount; ++f) parent_[f] = static_cast<uint32_t>(f);
  }
  uint32_t Root(uint32_t f) {
    while (parent_[f] != f) f = parent_[f] = parent_[parent_[f]];
    return f;
  }
  void Join(uint32_t f, uint32_t g) { parent_[Root(f)] = Root(g); }

 private:
  std::vector<uint32_t> parent_;
};

// Six times the signed volume under a face's fan of triangles (divergence
// theorem; over a closed surface the sum is six times the enclosed volume).
double SixVolumeUnderFace(const Mesh& mesh, size_t face, std::span<const Vec3> points) {
  const auto corners = mesh.Face(face);
  double sum = 0.0;
  for (size_t i = 1; i + 1 < corners.size(); ++i) {
    sum += Dot(points[corners[0]], Cross(points[corners[i]], points[corners[i + 1]]));
  }
  return sum;
}

}  // namespace

void ReverseFace(Mesh& mesh, size_t face) {
  const size_t start = mesh.faceStarts[face], end = mesh.faceStarts[face + 1];
  if (end - start < 3) return;
  // Corners c0 c1 ... c(n-1) become c0 c(n-1) ... c1; the new edge j is the
  // old edge n-1-j run backwards, so the hidden flags reverse as a whole.
  std::reverse(mesh.faceCorners.begin() + static_cast<std::ptrdiff_t>(start + 1),
               mesh.faceCorners.begin() + static_cast<std::ptrdiff_t>(end));
  std::reverse(mesh.edgeHidden.begin() + static_cast<std::ptrdiff_t>(start),
               mesh.edgeHidden.begin() + static_cast<std::ptrdiff_t>(end));
}

size_t OrientClosedPartsOutward(Mesh& mesh, const EdgeAdjacency& edges,
                                std::span<const Vec3> points) {
  const size_t faceCount = mesh.FaceCount();
  // Step 1: parts through shared edges; a face on an edge that is not used
  // exactly once each way marks its part open.
  FaceParts parts(faceCount);
  std::vector<uint8_t> openFace(faceCount, 0);
  edges.ForEachEdge([&](uint32_t, std::span<const EdgeUse> uses) {
    const bool closedEdge = uses.size() == 2 && uses[0].forward != uses[1].forward;
    for (const EdgeUse& use : uses) {
      parts.Join(use.face, uses[0].face);
      if (!closedEdge) openFace[use.face] = 1;
    }
  });

  // Step 2: each part's volume and whether it is closed.
  std::vector<double> sixVolume(faceCount, 0.0);
  std::vector<uint8_t> openPart(faceCount, 0);
  for (uint32_t f = 0; f < faceCount; ++f) {
    const uint32_t root = parts.Root(f);
    sixVolume[root] += SixVolumeUnderFace(mesh, f, points);
    openPart[root] = openPart[root] | openFace[f];
  }

  // Step 3: reverse the faces of closed parts with negative volume (NaN from
  // non-finite coordinates is not negative: those parts stay as they are).
  size_t reversed = 0;
  for (uint32_t f = 0; f < faceCount; ++f) {
    const uint32_t root = parts.Root(f);
    if (openPart[root] == 0 && sixVolume[root] < 0.0) {
      ReverseFace(mesh, f);
      ++reversed;
    }
  }
  return reversed;
}

}  // namespace termshade
