#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "process/HugePages.h"
#include "process/LoadThreads.h"

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
  // Each face edge a -> b (a != b) of the faces in [faceBegin, faceEnd).
  auto forEachFaceEdge = [&faces](size_t faceBegin, size_t faceEnd, auto&& use) {
    for (auto face = static_cast<uint32_t>(faceBegin); face < faceEnd; ++face) {
      const auto corners = faces.Face(face);
      const size_t n = corners.size();
      for (size_t i = 0; i < n; ++i) {
        const uint32_t a = corners[i], b = corners[i + 1 == n ? 0 : i + 1];
        if (a != b) use(a, b, face, i);
      }
    }
  };
  // Steps 1 and 2, a counting sort by smaller vertex, split by faces over
  // the load threads: each counts its faces' edges per vertex, and places
  // them after those of the faces before its own (the arrays one pass gives).
  const int threads = LoadThreadCount(faceCount);
  const auto parts = static_cast<size_t>(std::max(threads, 1));
  std::vector<std::vector<uint32_t>> placed(parts);  // per part and vertex: counts, then cursors
  for (std::vector<uint32_t>& part : placed) {
    part.reserve(vertexCount);
    AdviseHugePages(part);
    part.assign(vertexCount, 0);
  }

  // Step 1: how many edges start at each smaller vertex, per part.
  RunRangesOnLoadThreads(threads, faceCount, [&](int part, size_t begin, size_t end) {
    uint32_t* counts = placed[static_cast<size_t>(part)].data();
    forEachFaceEdge(begin, end, [counts](uint32_t a, uint32_t b, uint32_t, size_t) {
      ++counts[std::min(a, b)];
    });
  });
  starts_.reserve(vertexCount + 1);
  AdviseHugePages(starts_);
  starts_.resize(vertexCount + 1);
  uint32_t total = 0;
  for (size_t v = 0; v < vertexCount; ++v) {
    starts_[v] = total;
    for (std::vector<uint32_t>& part : placed) {
      const uint32_t count = part[v];
      part[v] = total;  // where the part's first use of v goes
      total += count;
    }
  }
  starts_[vertexCount] = total;

  // Step 2: place each use in its vertex's range, faces in order.
  ResizeFaultedIn(uses_, total);
  RunRangesOnLoadThreads(threads, faceCount, [&](int part, size_t begin, size_t end) {
    uint32_t* cursors = placed[static_cast<size_t>(part)].data();
    forEachFaceEdge(begin, end, [&](uint32_t a, uint32_t b, uint32_t face, size_t i) {
      uses_[cursors[std::min(a, b)]++] = {std::max(a, b), face, a < b, faces.EdgeHidden(face, i)};
    });
  });
  placed.clear();  // freed for the next arrays (orientation's) to reuse

  // Step 3: within a vertex, by larger vertex, then face; the vertices
  // split over the load threads.
  RunRangesOnLoadThreads(threads, vertexCount, [this](int, size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      std::sort(uses_.begin() + starts_[v], uses_.begin() + starts_[v + 1],
                [](const EdgeUse& p, const EdgeUse& q) { return p.SortKey() < q.SortKey(); });
    }
  });
}

}  // namespace termshade
