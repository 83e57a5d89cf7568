#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace termshade {

struct CastFrame;
struct TilePlanes;

/// A tile of samples: columns [col0, col1), rows [row0, row1).
struct Tile {
  int col0, row0, col1, row1;
};

// Where a tile's rays start: the subtrees its samples' widened beams may
// enter, found once a tile (the pyramid through its corner samples, boxes
// widened by the margin, cones applied), farthest first, four a group.
// Every ray tests the groups' boxes as it would a node's children.
struct alignas(16) EntryGroup {
  float low[3][4];
  float high[3][4];
  float nearestDepth[4];
  uint32_t ref[4];  ///< RayBvh::kEmpty in an unused slot (its box empty)
  uint32_t allFront[4];
};

/// A subtree the tile reaches, while they are being found.
struct TileCandidate {
  uint32_t ref;
  uint32_t allFront;
  float nearestDepth;
  float low[3], high[3];
};

/// One worker's tile: its entries and the scratch lists that find them.
struct alignas(64) TileEntries {
  std::vector<TileCandidate> candidates, expanded;
  std::vector<EntryGroup> groups;
};

/// Finds a tile's entries: from the root, level by level, the children
/// inside the tile's pyramid (through its corner samples; every box widened
/// by the frame's margin) whose cones do not face away, while there are at
/// most kMaxEntries of them.
class TileFrontier {
 public:
  static constexpr size_t kMaxEntries = 16;

  explicit TileFrontier(const CastFrame& cast) : cast_(cast) {}

  /// Fills entries.groups for the tile, farthest first.
  void Find(const Tile& tile, TileEntries& entries) const;

 private:
  void AddChildren(uint32_t ref, uint32_t allFront, const TilePlanes& planes,
                   std::vector<TileCandidate>& out) const;

  const CastFrame& cast_;
};

}  // namespace termshade
