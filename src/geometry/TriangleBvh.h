#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#include "geometry/Clusters.h"
#include "geometry/Vec3.h"

namespace termshade {

struct Scene;

/// One node of a TriangleBvh (world space): an oriented box holding its
/// triangles' corners and the normal cone of their faces. A point of the node
/// is center + s0 axes[0] + s1 axes[1] + s2 axes[2] with |sk| <= half[k]
/// (float axes, near orthonormal; the bounds hold for them as stored).
struct BvhNode {
  float center[3];
  float axes[3][3];  ///< axes[2]: the cone's axis when it has one
  float half[3];
  /// Every face's unit normal n has n . axes[2] >= coneCos (coneCos <= 0: no
  /// usable cone; kAllDegenerate: no face can face a point), and
  /// n . center - offset lies in [heightMin, heightMax] (heightMin -inf when
  /// a face is degenerate: never all toward).
  float coneCos;
  float heightMin;
  float heightMax;
  uint32_t first;  ///< leaf: its first scene triangle; inner: the right child
  uint32_t count;  ///< leaf: its triangles (> 0); inner: 0 (the left child is the next node)

  static constexpr float kAllDegenerate = 2.0F;
  Vec3 Center() const { return {center[0], center[1], center[2]}; }
  Vec3 Axis(int k) const { return {axes[k][0], axes[k][1], axes[k][2]}; }
  /// At least the distance from the center to any point of the node (loose:
  /// the half extents summed).
  double Radius() const {
    return (half[0] * Length(Axis(0)) + half[1] * Length(Axis(1)) + half[2] * Length(Axis(2))) *
           (1.0 + 1e-9);
  }
  /// The same, tight: the farthest of the box's corners.
  double CornerRadius() const {
    double farthest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3 p{};
      for (int k = 0; k < 3; ++k) p = p + Axis(k) * ((corner >> k & 1) != 0 ? half[k] : -half[k]);
      farthest = std::max(farthest, Length(p));
    }
    return farthest * (1.0 + 1e-9);
  }
};

/// A bounding-volume hierarchy over a scene's triangles (HierarchyStage): leaves
/// are runs of kLeafTriangles triangles in scene order (so a frame reads them
/// in memory order), the tree above them halves the leaves by count in
/// Morton order of their centers; nodes in depth-first order. Bounds are
/// conservative: no corner lies outside its node's box, no face's normal
/// outside its cone.
struct TriangleBvh {
  static constexpr uint32_t kLeafTriangles = 8;
  std::vector<BvhNode> nodes;
  /// The triangles and vertices it was built over (their arrays and counts).
  const void* trianglesData = nullptr;
  size_t triangleCount = 0;
  const void* verticesData = nullptr;
  size_t vertexCount = 0;

  bool Empty() const { return nodes.empty(); }
  size_t Bytes() const { return nodes.size() * sizeof(BvhNode); }
  bool BuiltFor(const Scene& scene) const;
};

/// Builds the hierarchy (on the load threads). A set `cancel` stops it early
/// with an empty hierarchy.
TriangleBvh BuildTriangleBvh(const Scene& scene, const std::atomic<bool>* cancel = nullptr);

/// Which way a node's faces turn as seen from a point: conservative, so
/// kAway and kToward hold for every face (FacePlane::FacesPoint, rounding included).
ClusterFacing NodeFacing(const BvhNode& node, Vec3 eyeWorld);

}  // namespace termshade
