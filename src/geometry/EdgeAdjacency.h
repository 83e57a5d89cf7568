#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "geometry/HugePages.h"
#include "geometry/LoadThreads.h"

namespace termshade {

/// One face's use of an undirected edge, in 8 bytes (faces below 2^30).
class EdgeUse {
 public:
  EdgeUse() = default;
  EdgeUse(uint32_t highVertex, uint32_t face, bool forward, bool hidden)
      : highVertex(highVertex),
        faceFlags_(face << 2 | static_cast<uint32_t>(forward) << 1 |
                   static_cast<uint32_t>(hidden)) {}
  uint32_t highVertex = 0;  ///< the edge's larger vertex number
  uint32_t Face() const { return faceFlags_ >> 2; }
  /// The face runs from the smaller vertex to the larger.
  bool Forward() const { return (faceFlags_ & 2) != 0; }
  /// The face hides the edge as a drawn line.
  bool Hidden() const { return (faceFlags_ & 1) != 0; }
  /// Orders by larger vertex, then face.
  uint64_t SortKey() const { return uint64_t{highVertex} << 32 | faceFlags_; }

 private:
  uint32_t faceFlags_ = 0;
};

/// Every face edge of a mesh, grouped by undirected edge: sorted arrays
/// (a counting sort by the smaller vertex, then each vertex's uses sorted by
/// larger vertex and face). Zero-length edges are left out.
class EdgeAdjacency {
 public:
  static constexpr size_t kMaxFaces = size_t{1} << 30;

  /// faces: anything with FaceCount(), Face(f) (corner indices below
  /// vertexCount) and EdgeHidden(f, i) (Mesh, FaceList, Scene).
  template <typename Faces>
  EdgeAdjacency(size_t vertexCount, const Faces& faces);

  /// Frees the arrays, their pages handed back (HugePages.h); empty after.
  void ReleasePages() {
    FreeAndReleasePages(starts_);
    FreeAndReleasePages(uses_);
  }

  /// Face edges in all (each undirected edge once per face that has it).
  size_t UseCount() const { return uses_.size(); }

  /// Calls visit(lowVertex, uses) once per undirected edge, in (low, high)
  /// order; the uses are sorted by face.
  template <typename Visit>
  void ForEachEdge(Visit&& visit) const {
    ForEachEdgeFrom(0, VertexCount(), visit);
  }

  /// The vertices the edges are numbered over.
  uint32_t VertexCount() const {
    return starts_.empty() ? 0 : static_cast<uint32_t>(starts_.size() - 1);
  }

  /// ForEachEdge for the edges whose smaller vertex is in [lowBegin, lowEnd):
  /// disjoint ranges split the edges (for threads).
  template <typename Visit>
  void ForEachEdgeFrom(uint32_t lowBegin, uint32_t lowEnd, Visit&& visit) const {
    for (uint32_t low = lowBegin; low < lowEnd; ++low) {
      const EdgeUse* use = uses_.data() + starts_[low];
      const EdgeUse* const end = uses_.data() + starts_[low + 1];
      while (use != end) {
        const EdgeUse* next = use + 1;
        while (next != end && next->highVertex == use->highVertex) ++next;
        visit(low, std::span<const EdgeUse>(use, next));
        use = next;
      }
    }
  }

 private:
  std::vector<uint32_t> starts_;  ///< per vertex, into uses_; one more entry than vertices
  std::vector<EdgeUse> uses_;
};

template <typename Faces>
EdgeAdjacency::EdgeAdjacency(size_t vertexCount, const Faces& faces) {
  const size_t faceCount = faces.FaceCount();
  if (faceCount >= kMaxFaces) throw std::length_error("more than 2^30 faces");
  auto forEachFaceEdge = [&faces, faceCount](auto&& use) {
    for (uint32_t face = 0; face < faceCount; ++face) {
      const auto corners = faces.Face(face);
      for (size_t i = 0; i < corners.size(); ++i) {
        const uint32_t a = corners[i], b = corners[(i + 1) % corners.size()];
        if (a != b) use(a, b, face, i);
      }
    }
  };
  // Step 1: how many edges start at each smaller vertex.
  starts_.reserve(vertexCount + 1);
  AdviseHugePages(starts_);
  starts_.assign(vertexCount + 1, 0);
  forEachFaceEdge([&](uint32_t a, uint32_t b, uint32_t, size_t) { ++starts_[std::min(a, b) + 1]; });
  for (size_t v = 0; v < vertexCount; ++v) starts_[v + 1] += starts_[v];

  // Step 2: place each use in its vertex's range.
  ResizeFaultedIn(uses_, starts_.back());
  {
    std::vector<uint32_t> filled(starts_.begin(), starts_.end() - 1);
    forEachFaceEdge([&](uint32_t a, uint32_t b, uint32_t face, size_t i) {
      uses_[filled[std::min(a, b)]++] = {std::max(a, b), face, a < b, faces.EdgeHidden(face, i)};
    });
  }

  // Step 3: within a vertex, by larger vertex, then face; the vertices
  // split over the load threads.
  const int threads = LoadThreadCount(uses_.size());
  RunOnLoadThreads(threads, [this, vertexCount, threads](int part) {
    const size_t begin = vertexCount * static_cast<size_t>(part) / static_cast<size_t>(threads);
    const size_t end = vertexCount * static_cast<size_t>(part + 1) / static_cast<size_t>(threads);
    for (size_t v = begin; v < end; ++v) {
      std::sort(uses_.begin() + starts_[v], uses_.begin() + starts_[v + 1],
                [](const EdgeUse& p, const EdgeUse& q) { return p.SortKey() < q.SortKey(); });
    }
  });
}

}  // namespace termshade
