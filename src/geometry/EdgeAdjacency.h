#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/Mesh.h"

namespace termshade {

/// One face's use of an undirected edge.
struct EdgeUse {
  uint32_t highVertex = 0;  ///< the edge's larger vertex number
  uint32_t face = 0;
  bool forward = false;  ///< the face runs from the smaller vertex to the larger
  bool hidden = false;   ///< the face hides the edge as a drawn line
};

/// Every face edge of a mesh, grouped by undirected edge: sorted arrays
/// (a counting sort by the smaller vertex, then each vertex's uses sorted by
/// larger vertex and face). Zero-length edges are left out.
class EdgeAdjacency {
 public:
  explicit EdgeAdjacency(const Mesh& mesh);

  /// Face edges in all (each undirected edge once per face that has it).
  size_t UseCount() const { return uses_.size(); }

  /// Calls visit(lowVertex, uses) once per undirected edge, in (low, high)
  /// order; the uses are sorted by face.
  template <typename Visit>
  void ForEachEdge(Visit&& visit) const {
    for (uint32_t low = 0; low + 1 < starts_.size(); ++low) {
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

}  // namespace termshade
