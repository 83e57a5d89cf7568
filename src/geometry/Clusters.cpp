#include "geometry/Clusters.h"

#include <algorithm>
#include <cmath>

#include "geometry/Scene.h"

namespace termshade {
namespace {

// Bounding sphere about the box center of the corners, a hair larger than
// the farthest corner so rounding cannot leave one outside.
void FitSphere(const Scene& scene, std::span<const uint32_t> members, SceneCluster& c) {
  Vec3 low = scene.verticesWorld[scene.triangles[members.front()].vertices[0]], high = low;
  for (const uint32_t t : members) {
    for (const uint32_t v : scene.triangles[t].vertices) {
      const Vec3 p = scene.verticesWorld[v];
      low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
  }
  c.centerWorld = (low + high) * 0.5;
  double radius = 0.0;
  for (const uint32_t t : members) {
    for (const uint32_t v : scene.triangles[t].vertices) {
      radius = std::max(radius, Length(scene.verticesWorld[v] - c.centerWorld));
    }
  }
  c.radius = radius * (1.0 + 1e-9) + 1e-300;
}

// Calls visit(plane) once per run of the cluster's triangles sharing a face.
template <typename Visit>
void ForEachFace(const Scene& scene, std::span<const uint32_t> members, Visit&& visit) {
  uint32_t lastFace = UINT32_MAX;
  for (const uint32_t t : members) {
    const uint32_t face = scene.triangles[t].face;
    if (face == lastFace) continue;
    lastFace = face;
    visit(scene.facePlanesWorld[face]);
  }
}

// The cone of the faces' unit normals about their normalized sum, widened a
// little for rounding; faces with a zero normal are never front-facing and
// do not count.
void FitCone(const Scene& scene, std::span<const uint32_t> members, SceneCluster& c) {
  Vec3 sum{};
  bool any = false;
  ForEachFace(scene, members, [&](const FacePlane& plane) {
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
  ForEachFace(scene, members, [&](const FacePlane& plane) {
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

// 10 bits of a coordinate spread to every third bit.
uint32_t SpreadBits(uint32_t x) {
  x = (x | (x << 16)) & 0x030000FFU;
  x = (x | (x << 8)) & 0x0300F00FU;
  x = (x | (x << 4)) & 0x030C30C3U;
  x = (x | (x << 2)) & 0x09249249U;
  return x;
}

// Runs of this many consecutive triangles stay together: a cluster reads a
// few runs of neighbouring memory rather than 64 scattered triangles.
constexpr size_t kRunTriangles = 16;

// The triangles ordered along a Morton curve of the centroids of their runs
// (ties in scene order): neighbours on the surface come out close together.
std::vector<uint32_t> MortonOrder(const Scene& scene) {
  const size_t count = scene.triangles.size();
  const size_t runCount = (count + kRunTriangles - 1) / kRunTriangles;
  std::vector<Vec3> centroids(runCount);
  Vec3 low{INFINITY, INFINITY, INFINITY}, high = low * -1.0;
  for (size_t r = 0; r < runCount; ++r) {
    Vec3 sum{};
    for (size_t t = r * kRunTriangles; t < std::min(count, (r + 1) * kRunTriangles); ++t) {
      for (const uint32_t v : scene.triangles[t].vertices) sum = sum + scene.verticesWorld[v];
    }
    centroids[r] = sum;
    if (!IsFinite(sum)) continue;
    low = {std::min(low.x, sum.x), std::min(low.y, sum.y), std::min(low.z, sum.z)};
    high = {std::max(high.x, sum.x), std::max(high.y, sum.y), std::max(high.z, sum.z)};
  }
  auto quantize = [](double value, double from, double to) {
    const double unit = (value - from) / (to - from);
    if (!(unit > 0.0)) return 0U;  // NaN too
    return static_cast<uint32_t>(std::min(1023.0, unit * 1024.0));
  };
  std::vector<uint32_t> codes(runCount), order(runCount), codesOut(runCount), orderOut(runCount);
  for (size_t r = 0; r < runCount; ++r) {
    const Vec3 p = centroids[r];
    codes[r] = SpreadBits(quantize(p.x, low.x, high.x)) |
               (SpreadBits(quantize(p.y, low.y, high.y)) << 1) |
               (SpreadBits(quantize(p.z, low.z, high.z)) << 2);
    order[r] = static_cast<uint32_t>(r);
  }
  // Stable LSD radix sort, three passes of 10 bits.
  for (int shift = 0; shift < 30; shift += 10) {
    std::vector<uint32_t> starts(1025, 0);
    for (size_t i = 0; i < runCount; ++i) ++starts[((codes[i] >> shift) & 1023U) + 1];
    for (size_t b = 1; b < starts.size(); ++b) starts[b] += starts[b - 1];
    for (size_t i = 0; i < runCount; ++i) {
      const uint32_t slot = starts[(codes[i] >> shift) & 1023U]++;
      codesOut[slot] = codes[i];
      orderOut[slot] = order[i];
    }
    codes.swap(codesOut);
    order.swap(orderOut);
  }
  std::vector<uint32_t> triangles;
  triangles.reserve(count);
  for (const uint32_t r : order) {
    for (size_t t = r * kRunTriangles; t < std::min(count, (r + 1) * kRunTriangles); ++t) {
      triangles.push_back(static_cast<uint32_t>(t));
    }
  }
  return triangles;
}

}  // namespace

SceneClusters BuildClusters(const Scene& scene) {
  SceneClusters out;
  const size_t triangleCount = scene.triangles.size();
  out.sceneOrder = triangleCount < SceneClusters::kSpatialFromTriangles;
  if (out.sceneOrder) {
    out.triangles.resize(triangleCount);
    for (size_t t = 0; t < triangleCount; ++t) out.triangles[t] = static_cast<uint32_t>(t);
  } else {
    out.triangles = MortonOrder(scene);
  }
  out.clusters.reserve(triangleCount / SceneClusters::kMaxTriangles + 1);
  out.corners.resize(triangleCount);
  out.faces.resize(triangleCount);
  std::vector<uint32_t> local(scene.verticesWorld.size(), UINT32_MAX);
  for (size_t t = 0; t < triangleCount; t += SceneClusters::kMaxTriangles) {
    SceneCluster c;
    c.first = static_cast<uint32_t>(t);
    c.end = static_cast<uint32_t>(std::min(triangleCount, t + SceneClusters::kMaxTriangles));
    std::sort(out.triangles.begin() + c.first, out.triangles.begin() + c.end);
    const std::span<const uint32_t> members = out.Of(c);
    // Its distinct vertices, and each corner as an index among them.
    c.vertexFirst = static_cast<uint32_t>(out.vertices.size());
    for (uint32_t i = c.first; i < c.end; ++i) {
      out.faces[i] = scene.triangles[out.triangles[i]].face;
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = scene.triangles[out.triangles[i]].vertices[k];
        if (local[v] == UINT32_MAX) {
          local[v] = static_cast<uint32_t>(out.vertices.size()) - c.vertexFirst;
          out.vertices.push_back(v);
        }
        out.corners[i][k] = static_cast<uint8_t>(local[v]);
      }
    }
    c.vertexEnd = static_cast<uint32_t>(out.vertices.size());
    for (uint32_t i = c.vertexFirst; i < c.vertexEnd; ++i) local[out.vertices[i]] = UINT32_MAX;
    FitSphere(scene, members, c);
    FitCone(scene, members, c);
    out.clusters.push_back(c);
  }
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
  const double across = std::sqrt(std::max(0.0, length * length - along * along));
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
