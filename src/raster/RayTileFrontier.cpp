#include "raster/RayTileFrontier.h"

#include <algorithm>
#include <cmath>

#include "raster/RayCastFrame.h"

namespace termshade {

// The four side planes of the pyramid from the eye through a tile's corner
// samples, each with its normal towards the inside (world space, double).
struct TilePlanes {
  Vec3 normal[4];
  double offset[4];    ///< normal . eye
  double widening[4];  ///< margin |normal|_1 and the rounding of the test
};

namespace {

TilePlanes MakePlanes(const CastFrame& cast, const Tile& tile) {
  const Vec3 topLeft = SampleDirection(cast, tile.col0, tile.row0);
  const Vec3 topRight = SampleDirection(cast, tile.col1 - 1, tile.row0);
  const Vec3 bottomLeft = SampleDirection(cast, tile.col0, tile.row1 - 1);
  const Vec3 bottomRight = SampleDirection(cast, tile.col1 - 1, tile.row1 - 1);
  const Vec3 center = topLeft + topRight + bottomLeft + bottomRight;
  const Vec3 edges[4][2] = {{topLeft, bottomLeft},
                            {topRight, bottomRight},
                            {topLeft, topRight},
                            {bottomLeft, bottomRight}};
  const Vec3 eye{cast.eye[0], cast.eye[1], cast.eye[2]};
  TilePlanes planes{};
  for (int p = 0; p < 4; ++p) {
    // Every sample direction of the tile is a convex combination of the
    // corners', so inside all four planes (a one-sample-wide tile's two
    // planes coincide: either side holds them).
    Vec3 n = Cross(edges[p][0], edges[p][1]);
    if (Dot(n, center) < 0.0) n = n * -1.0;
    const double l1 = std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
    planes.normal[p] = n;
    planes.offset[p] = Dot(n, eye);
    planes.widening[p] = l1 * (double{cast.margin} + 1e-9 * cast.coordinateReach);
  }
  return planes;
}

// False when the child's box, widened by the margin, lies wholly outside a plane.
bool InPyramid(const RayBvhNode& node, int child, const TilePlanes& planes) {
  for (int p = 0; p < 4; ++p) {
    const Vec3& n = planes.normal[p];
    const double reach = n.x * (n.x >= 0.0 ? node.high[0][child] : node.low[0][child]) +
                         n.y * (n.y >= 0.0 ? node.high[1][child] : node.low[1][child]) +
                         n.z * (n.z >= 0.0 ? node.high[2][child] : node.low[2][child]);
    if (reach - planes.offset[p] + planes.widening[p] < 0.0) return false;
  }
  return true;
}

void Pack(const std::vector<TileCandidate>& list, std::vector<EntryGroup>& groups) {
  groups.assign((list.size() + 3) / 4, EntryGroup{});
  for (size_t g = 0; g < groups.size(); ++g) {
    EntryGroup& group = groups[g];
    for (size_t i = 0; i < 4; ++i) {
      const size_t at = 4 * g + i;
      const bool used = at < list.size();
      group.ref[i] = used ? list[at].ref : RayBvh::kEmpty;
      group.allFront[i] = used ? list[at].allFront : 0;
      group.nearestDepth[i] = used ? list[at].nearestDepth : INFINITY;
      for (int k = 0; k < 3; ++k) {
        group.low[k][i] = used ? list[at].low[k] : INFINITY;
        group.high[k][i] = used ? list[at].high[k] : -INFINITY;
      }
    }
  }
}

}  // namespace

void TileFrontier::Find(const Tile& tile, TileEntries& entries) const {
  const TilePlanes planes = MakePlanes(cast_, tile);
  std::vector<TileCandidate>& list = entries.candidates;
  std::vector<TileCandidate>& next = entries.expanded;
  list.clear();
  AddChildren(0, 0, planes, list);
  // Level by level, while the list stays within its size.
  for (bool grew = true; grew;) {
    grew = false;
    next.clear();
    for (size_t i = 0; i < list.size(); ++i) {
      const size_t before = next.size();
      const bool room = before + (list.size() - i) - 1 + 4 <= kMaxEntries;
      if (room && !RayBvh::IsLeaf(list[i].ref)) {
        AddChildren(list[i].ref, list[i].allFront, planes, next);
        grew = true;
      } else {
        next.push_back(list[i]);
      }
    }
    list.swap(next);
  }
  std::sort(list.begin(), list.end(), [](const TileCandidate& a, const TileCandidate& b) {
    return a.nearestDepth != b.nearestDepth ? a.nearestDepth > b.nearestDepth : a.ref < b.ref;
  });
  Pack(list, entries.groups);
}

// The node's children inside the tile's pyramid, unless its cone faces away.
void TileFrontier::AddChildren(uint32_t ref, uint32_t allFront, const TilePlanes& planes,
                               std::vector<TileCandidate>& out) const {
  const RayBvhNode& node = cast_.bvh.nodes[ref];
  if (allFront == 0) {
    const ClusterFacing facing = ConeFacing(node.cone, cast_.frame.eyeWorld, cast_.eyeLength);
    if (facing == ClusterFacing::kAway) return;
    allFront = facing == ClusterFacing::kToward ? 1 : 0;
  }
  const Floats4 depth = NearestDepths(cast_, &node.low[0][0], &node.high[0][0]);
  for (int i = 0; i < 4; ++i) {
    if (node.child[i] == RayBvh::kEmpty || !InPyramid(node, i, planes)) continue;
    TileCandidate c{node.child[i], allFront, depth[i], {}, {}};
    for (int k = 0; k < 3; ++k) {
      c.low[k] = node.low[k][i];
      c.high[k] = node.high[k][i];
    }
    out.push_back(c);
  }
}

}  // namespace termshade
