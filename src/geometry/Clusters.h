#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/Vec3.h"

namespace termshade {

struct Scene;

/// Up to 64 scene triangles with a bounding sphere and a normal cone, so a
/// frame can skip the whole cluster before any per-triangle work when it
/// faces away or covers no sample.
struct SceneCluster {
  uint32_t first = 0;  ///< into SceneClusters::triangles and corners (a multiple of kMaxTriangles)
  uint32_t end = 0;
  uint32_t vertexFirst = 0;  ///< into SceneClusters::positions
  uint32_t vertexEnd = 0;
  Vec3 centerWorld;  ///< bounding sphere of the triangles' corners
  double radius = 0.0;
  /// Normal cone of its faces' planes: every unit normal n has n . axis >= coneCos
  /// (coneCos <= 0: no usable cone); n . center - offset lies in [heightMin, heightMax].
  Vec3 coneAxis;
  double coneCos = -1.0;
  double heightMin = 0.0;
  double heightMax = 0.0;
  bool allDegenerate = false;  ///< every face zero-normal: never front-facing
  bool anyDegenerate = false;
};

/// Eight consecutive entries of a cluster (its last group may hold fewer):
/// a bounding sphere in float, checked per frame only where the cluster's
/// own sphere projects wholly on the direct path (VertexStage).
struct ClusterGroup {
  float center[3] = {0.0F, 0.0F, 0.0F};
  float radius = 0.0F;  ///< rounded up: every corner of its triangles lies inside
};

/// The clusters of a scene, built once at preparation.
struct SceneClusters {
  static constexpr uint32_t kMaxTriangles = 64;
  static constexpr uint32_t kGroupTriangles = 8;
  /// From this many triangles clusters are spatial (Morton order of the
  /// triangles' centroids); below, runs in scene order.
  static constexpr size_t kSpatialFromTriangles = 20000;
  std::vector<SceneCluster> clusters;
  std::vector<uint32_t> triangles;  ///< into Scene::triangles, cluster by cluster
  /// Per entry of triangles: its corners as indices into its cluster's vertices.
  std::vector<std::array<uint8_t, 3>> corners;
  std::vector<ClusterGroup> groups;  ///< per kGroupTriangles entries of triangles
  /// Each cluster's distinct vertices, copied from Scene::verticesWorld in
  /// first-use order: a frame reads a group's corners from a few cache lines.
  std::vector<Vec3> positions;
  bool sceneOrder = true;          ///< triangles is 0, 1, 2, ...: the clusters keep the scene order

  /// A cluster's triangles (Scene::triangles indices).
  std::span<const uint32_t> Of(const SceneCluster& c) const {
    return std::span<const uint32_t>(triangles).subspan(c.first, c.end - c.first);
  }
};

/// Groups the scene's triangles into clusters of up to kMaxTriangles: runs in
/// scene order for small scenes, neighbours along a Morton curve of their
/// centroids for big ones (so a cluster and each of its groups are compact).
SceneClusters BuildClusters(const Scene& scene);

/// Which way a cluster's faces turn as seen from a point: conservative, so
/// kAway and kToward hold for every face (FacePlane::FacesPoint, rounding included).
enum class ClusterFacing { kAway, kToward, kMixed };
ClusterFacing FacingOf(const SceneCluster& cluster, Vec3 eyeWorld);

}  // namespace termshade
