#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Vec3.h"

namespace termshade {

struct Scene;

/// A run of consecutive scene triangles (scene order kept) with a bounding
/// sphere and a normal cone, so a frame can skip the whole run before any
/// per-triangle work when it faces away or covers no sample.
struct SceneCluster {
  uint32_t firstTriangle = 0;  ///< into Scene::triangles
  uint32_t triangleEnd = 0;
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

/// The clusters of a scene, built once at preparation.
struct SceneClusters {
  static constexpr uint32_t kMaxTriangles = 64;
  std::vector<SceneCluster> clusters;
};

/// Groups the scene's triangles, in order, into runs of kMaxTriangles.
SceneClusters BuildClusters(const Scene& scene);

/// Which way a cluster's faces turn as seen from a point: conservative, so
/// kAway and kToward hold for every face (FacePlane::FacesPoint, rounding included).
enum class ClusterFacing { kAway, kToward, kMixed };
ClusterFacing FacingOf(const SceneCluster& cluster, Vec3 eyeWorld);

}  // namespace termshade
