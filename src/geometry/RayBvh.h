#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/Clusters.h"
#include "geometry/Vec3.h"

namespace termshade {

struct Scene;

/// The normal cone of a node's faces: every face's unit normal n has
/// n . axis / |axis| >= coneCos, and n . center - offset lies in [heightMin,
/// heightMax] (its plane n . p = offset). Floats; the bounds hold for them
/// as stored.
struct RayBvhCone {
  float center[3];
  float axis[3];    ///< unit within float rounding; x when coneCos is kNoCone or kAllAway
  float coneCos;    ///< kNoCone: none usable; kAllAway: no face can face any point
  float heightMin;  ///< -inf when a face is degenerate (such a face never faces a point)
  float heightMax;  ///< both widened past the rounding of the stored center and axis
  static constexpr float kNoCone = -2.0F;
  static constexpr float kAllAway = 2.0F;
};

/// One node of a RayBvh, three cache lines: the world-space boxes of up to
/// four children, as structure of arrays (four children a SIMD register);
/// each child's slab along the node's cone axis (x where the faces have no
/// usable cone): a . p lies in [slabLow, slabHigh] for every corner p of the
/// child's triangles; and the node's own normal cone. Floats rounded
/// outward, so every corner lies inside.
struct alignas(64) RayBvhNode {
  float low[3][4];   ///< [axis][child]
  float high[3][4];  ///< [axis][child]
  float slabLow[4];
  float slabHigh[4];
  /// Per child: an inner node's index; a leaf as RayBvh::LeafRef; or
  /// RayBvh::kEmpty (its box is empty: low > high).
  uint32_t child[4];
  RayBvhCone cone;  ///< its axis is the slabs' axis
};

/// One triangle of a leaf as the rays read it: its corners' vertex indices
/// and its scene index, so a leaf's four triangles are one cache line
/// fetched with the node that points to it (no scene triangle read between).
struct RayBvhLeafTriangle {
  uint32_t vertices[3];
  uint32_t triangle;  ///< index in Scene::triangles
  bool operator==(const RayBvhLeafTriangle&) const = default;
};

/// Which way the faces of the cone's node turn as seen from pWorld:
/// conservative, so kAway and kToward hold for every face
/// (FacePlane::FacesPoint, rounding included); pLength = |pWorld|.
ClusterFacing ConeFacing(const RayBvhCone& cone, Vec3 pWorld, double pLength);

/// A four-wide bounding-volume hierarchy over a scene's triangles for
/// finding, per sample, the triangles that may cover it (RayCastStage).
/// Triangles are sorted in Morton order of their centroids and split where
/// their codes first differ; leaves hold up to kLeafTriangles of them.
struct RayBvh {
  static constexpr uint32_t kLeafTriangles = 4;
  static constexpr uint32_t kLeafBit = 1U << 31;
  static constexpr uint32_t kCountBits = 3;
  static constexpr uint32_t kEmpty = UINT32_MAX;
  /// Scenes of this many triangles or more are not served (leaf references
  /// keep a triangle offset in 28 bits).
  static constexpr size_t kMaxTriangles = size_t{1} << 28;

  std::vector<RayBvhNode> nodes;              ///< nodes[0] is the root (when not empty)
  std::vector<RayBvhLeafTriangle> triangles;  ///< each leaf a run of them
  float low[3] = {0, 0, 0};                   ///< the root's box, world space
  float high[3] = {0, 0, 0};
  /// The triangles and vertices it was built over (their arrays and counts).
  const void* trianglesData = nullptr;
  size_t triangleCount = 0;
  const void* verticesData = nullptr;
  size_t vertexCount = 0;

  static constexpr uint32_t LeafRef(uint32_t first, uint32_t count) {
    return kLeafBit | first << kCountBits | count;
  }
  static constexpr bool IsLeaf(uint32_t ref) { return ref != kEmpty && (ref & kLeafBit) != 0; }
  static constexpr uint32_t LeafFirst(uint32_t ref) { return (ref & ~kLeafBit) >> kCountBits; }
  static constexpr uint32_t LeafCount(uint32_t ref) { return ref & ((1U << kCountBits) - 1); }

  bool Empty() const { return nodes.empty(); }
  size_t Bytes() const {
    return nodes.size() * sizeof(RayBvhNode) + triangles.size() * sizeof(RayBvhLeafTriangle);
  }
  bool BuiltFor(const Scene& scene) const;
};

/// Builds the hierarchy. A set `cancel` stops it early with an empty one;
/// scenes of kMaxTriangles or more get an empty one. `threads` 0: the load
/// threads' count for the scene; from two, big scenes build the root's
/// subtrees on two threads (the same hierarchy, byte for byte).
RayBvh BuildRayBvh(const Scene& scene, const std::atomic<bool>* cancel = nullptr, int threads = 0);

/// Peak bytes BuildRayBvh takes for the scene, the hierarchy it keeps
/// included: 32 a triangle allocated, 66 resident (huge pages, two threads)
/// measured on spheres (docs/load-and-memory.md), rounded up.
size_t EstimateRayBvhBytes(const Scene& scene);

}  // namespace termshade
