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
double SixVolumeUnderFace(const FaceList& faces, size_t face, std::span<const Vec3> points) {
  const auto corners = faces.Face(face);
  double sum = 0.0;
  for (size_t i = 1; i + 1 < corners.size(); ++i) {
    sum += Dot(points[corners[0]], Cross(points[corners[i]], points[corners[i + 1]]));
  }
  return sum;
}

}  // namespace

namespace {

// Corners c0 c1 ... c(n-1) become c0 c(n-1) ... c1; the new edge j is the
// old edge n-1-j run backwards, so the hidden flags (when kept) reverse as a whole.
void ReverseCorners(std::vector<uint32_t>& corners, std::vector<uint8_t>& hidden, size_t start,
                    size_t end) {
  if (end - start < 3) return;
  std::reverse(corners.begin() + static_cast<std::ptrdiff_t>(start + 1),
               corners.begin() + static_cast<std::ptrdiff_t>(end));
  if (hidden.empty()) return;
  std::reverse(hidden.begin() + static_cast<std::ptrdiff_t>(start),
               hidden.begin() + static_cast<std::ptrdiff_t>(end));
}

}  // namespace

void ReverseFace(Mesh& mesh, size_t face) {
  ReverseCorners(mesh.faceCorners, mesh.edgeHidden, mesh.faceStarts[face],
                 mesh.faceStarts[face + 1]);
}

void ReverseFace(FaceList& faces, size_t face) {
  ReverseCorners(faces.corners, faces.hidden, faces.Start(face), faces.Start(face + 1));
}

size_t OrientClosedPartsOutward(FaceList& faces, const EdgeAdjacency& edges,
                                std::span<const Vec3> points, bool* oneClosedPart) {
  const size_t faceCount = faces.FaceCount();
  // Step 1: parts through shared edges; a face on an edge that is not used
  // exactly once each way marks its part open.
  FaceParts parts(faceCount);
  std::vector<uint8_t> openFace(faceCount, 0);
  edges.ForEachEdge([&](uint32_t, std::span<const EdgeUse> uses) {
    const bool closedEdge = uses.size() == 2 && uses[0].Forward() != uses[1].Forward();
    for (const EdgeUse& use : uses) {
      parts.Join(use.Face(), uses[0].Face());
      if (!closedEdge) openFace[use.Face()] = 1;
    }
  });

  // Step 2: each part's volume and whether it is closed.
  std::vector<double> sixVolume(faceCount, 0.0);
  std::vector<uint8_t> openPart(faceCount, 0);
  for (uint32_t f = 0; f < faceCount; ++f) {
    const uint32_t root = parts.Root(f);
    sixVolume[root] += SixVolumeUnderFace(faces, f, points);
    openPart[root] = openPart[root] | openFace[f];
  }

  if (oneClosedPart != nullptr) {
    *oneClosedPart = faceCount > 0;
    for (uint32_t f = 0; f < faceCount && *oneClosedPart; ++f) {
      *oneClosedPart = openFace[f] == 0 && parts.Root(f) == parts.Root(0);
    }
  }

  // Step 3: reverse the faces of closed parts with negative volume (NaN from
  // non-finite coordinates is not negative: those parts stay as they are).
  size_t reversed = 0;
  for (uint32_t f = 0; f < faceCount; ++f) {
    const uint32_t root = parts.Root(f);
    if (openPart[root] == 0 && sixVolume[root] < 0.0) {
      ReverseFace(faces, f);
      ++reversed;
    }
  }
  return reversed;
}

}  // namespace termshade
