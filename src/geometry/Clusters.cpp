#include "geometry/Clusters.h"

#include <algorithm>
#include <cmath>

#include "geometry/Scene.h"
#include "process/LoadThreads.h"

namespace termshade {
namespace {

// Bounding sphere about the box center of the corners, a hair larger than
// the farthest corner so rounding cannot leave one outside.
void FitSphere(const Scene& scene, SceneCluster& c) {
  Vec3 low = scene.verticesWorld[scene.triangles[c.firstTriangle].vertices[0]], high = low;
  for (uint32_t t = c.firstTriangle; t < c.triangleEnd; ++t) {
    for (const uint32_t v : scene.triangles[t].vertices) {
      const Vec3 p = scene.verticesWorld[v];
      low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
  }
  c.centerWorld = (low + high) * 0.5;
  double radius = 0.0;
  for (uint32_t t = c.firstTriangle; t < c.triangleEnd; ++t) {
    for (const uint32_t v : scene.triangles[t].vertices) {
      radius = std::max(radius, Length(scene.verticesWorld[v] - c.centerWorld));
    }
  }
  c.radius = radius * (1.0 + 1e-9) + 1e-300;
}

// Calls visit(plane) once per run of the cluster's triangles sharing a face.
template <typename Visit>
void ForEachFace(const Scene& scene, const SceneCluster& c, Visit&& visit) {
  uint32_t lastFace = UINT32_MAX;
  for (uint32_t t = c.firstTriangle; t < c.triangleEnd; ++t) {
    const uint32_t face = scene.TriangleFace(t);
    if (face == lastFace) continue;
    lastFace = face;
    visit(scene.facePlanesWorld[face]);
  }
}

// The cone of the faces' unit normals about their normalized sum, widened a
// little for rounding; faces with a zero normal are never front-facing and
// do not count.
void FitCone(const Scene& scene, SceneCluster& c) {
  Vec3 sum{};
  bool any = false;
  ForEachFace(scene, c, [&](const FacePlane& plane) {
    if (Dot(plane.normal, plane.normal) == 0.0) {
      c.anyDegenerate = true;
      return;
    }
    sum = sum + plane.normal;
    any = true;
  });
  c.allDegenerate = !any;
  const double length = Length(sum);
  if (!any || !(length > 1e-6)) return;
  c.coneAxis = sum * (1.0 / length);
  double coneCos = 1.0, heightMin = INFINITY, heightMax = -INFINITY;
  ForEachFace(scene, c, [&](const FacePlane& plane) {
    if (Dot(plane.normal, plane.normal) == 0.0) return;
    coneCos = std::min(coneCos, Dot(plane.normal, c.coneAxis));
    const double height = Dot(plane.normal, c.centerWorld) - plane.offset;
    heightMin = std::min(heightMin, height);
    heightMax = std::max(heightMax, height);
  });
  c.coneCos = coneCos - 1e-9;
  c.heightMin = heightMin;
  c.heightMax = heightMax;
}

}  // namespace

SceneClusters BuildClusters(const Scene& scene) {
  SceneClusters out;
  constexpr size_t kRun = SceneClusters::kMaxTriangles;
  const size_t triangleCount = scene.triangles.size();
  out.clusters.resize((triangleCount + kRun - 1) / kRun);
  // Clusters are independent: contiguous ranges of them, one a load thread.
  const size_t clusterCount = out.clusters.size();
  const int threads = LoadThreadCount(triangleCount);
  RunOnLoadThreads(threads, [&](int part) {
    const size_t end = clusterCount * (part + 1) / threads;
    for (size_t i = clusterCount * part / threads; i < end; ++i) {
      SceneCluster& c = out.clusters[i];
      c.firstTriangle = static_cast<uint32_t>(i * kRun);
      c.triangleEnd = static_cast<uint32_t>(std::min(triangleCount, (i + 1) * kRun));
      FitSphere(scene, c);
      FitCone(scene, c);
    }
  });
  return out;
}

ClusterFacing FacingOf(const SceneCluster& cluster, Vec3 eyeWorld) {
  if (cluster.allDegenerate) return ClusterFacing::kAway;
  if (!(cluster.coneCos > 0.0)) return ClusterFacing::kMixed;
  // n . e - offset = n . (e - c) + (n . c - offset), with v = e - c. Over a
  // cone of half-angle t about a, at angle phi from v:
  // max n . v = |v| cos(phi - t) when phi > t, min n . v = |v| cos(phi + t)
  // when phi + t < 180 degrees; |v| cos(phi -+ t) = (a . v) cos t +- |a x v| sin t.
  const Vec3 v = eyeWorld - cluster.centerWorld;
  const double length = Length(v);
  const double along = Dot(cluster.coneAxis, v);
  const double across = Length(Cross(cluster.coneAxis, v));  // no cancellation near the axis
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cluster.coneCos * cluster.coneCos));
  // Margin for the rounding of these bounds and of FacesPoint itself.
  const double margin =
      1e-9 * (length + Length(eyeWorld) + Length(cluster.centerWorld) + cluster.radius);
  const double most = along * cluster.coneCos + across * sinT;
  if (along < length * cluster.coneCos && most + cluster.heightMax < -margin) {
    return ClusterFacing::kAway;
  }
  const double least = along * cluster.coneCos - across * sinT;
  // least > 0: phi + t < 90 degrees, where the formula holds.
  if (!cluster.anyDegenerate && least > 0.0 && least + cluster.heightMin > margin) {
    return ClusterFacing::kToward;
  }
  return ClusterFacing::kMixed;
}

}  // namespace termshade
