#include "geometry/OutwardOrientation.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "process/HugePages.h"

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

  /// Numbers the parts by their first face and returns how many there are;
  /// after it, Part(f) is face f's part and Root and Join are unusable.
  uint32_t NumberParts() {
    const auto faceCount = static_cast<uint32_t>(parent_.size());
    for (uint32_t f = 0; f < faceCount; ++f) parent_[f] = Root(f);  // each face at its root
    // A numbered entry carries kNumbered (faces are below 2^30): a root's
    // when its part was first met, a face's once it is read.
    uint32_t parts = 0;
    for (uint32_t f = 0; f < faceCount; ++f) {
      if ((parent_[f] & kNumbered) != 0) continue;  // a root numbered by an earlier face
      const uint32_t root = parent_[f];
      if ((parent_[root] & kNumbered) == 0) parent_[root] = kNumbered | parts++;
      parent_[f] = parent_[root];
    }
    return parts;
  }
  uint32_t Part(uint32_t f) const { return parent_[f] & ~kNumbered; }
  void Free() { FreeAndReleasePages(parent_); }

 private:
  static constexpr uint32_t kNumbered = uint32_t{1} << 31;
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
    for (size_t i = 1; i < uses.size(); ++i) parts.Join(uses[i].Face(), uses[0].Face());
    if (!closedEdge) {
      for (const EdgeUse& use : uses) openFace[use.Face()] = 1;
    }
  });

  // Step 2: each part's volume (its faces summed in order) and whether it
  // is closed.
  const uint32_t partCount = parts.NumberParts();
  std::vector<double> sixVolume(partCount, 0.0);
  std::vector<uint8_t> openPart(partCount, 0);
  for (uint32_t f = 0; f < faceCount; ++f) {
    const uint32_t part = parts.Part(f);
    sixVolume[part] += SixVolumeUnderFace(faces, f, points);
    openPart[part] = openPart[part] | openFace[f];
  }
  FreeAndReleasePages(openFace);
  if (oneClosedPart != nullptr) *oneClosedPart = partCount == 1 && openPart[0] == 0;

  // Step 3: reverse the faces of closed parts with negative volume (NaN from
  // non-finite coordinates is not negative: those parts stay as they are).
  size_t reversed = 0;
  for (uint32_t f = 0; f < faceCount; ++f) {
    const uint32_t part = parts.Part(f);
    if (openPart[part] == 0 && sixVolume[part] < 0.0) {
      ReverseFace(faces, f);
      ++reversed;
    }
  }
  parts.Free();
  return reversed;
}

}  // namespace termshade
