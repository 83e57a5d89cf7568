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

// The triangles ordered along a Morton curve of their centroids (ties in
// scene order): neighbours on the surface come out close together.
std::vector<uint32_t> MortonOrder(const Scene& scene) {
  const size_t count = scene.triangles.size();
  std::vector<Vec3> centroids(count);
  Vec3 low{INFINITY, INFINITY, INFINITY}, high = low * -1.0;
  for (size_t t = 0; t < count; ++t) {
    Vec3 sum{};
    for (const uint32_t v : scene.triangles[t].vertices) sum = sum + scene.verticesWorld[v];
    centroids[t] = sum;
    if (!IsFinite(sum)) continue;
    low = {std::min(low.x, sum.x), std::min(low.y, sum.y), std::min(low.z, sum.z)};
    high = {std::max(high.x, sum.x), std::max(high.y, sum.y), std::max(high.z, sum.z)};
  }
  auto quantize = [](double value, double from, double to) {
    const double unit = (value - from) / (to - from);
    if (!(unit > 0.0)) return 0U;  // NaN too
    return static_cast<uint32_t>(std::min(1023.0, unit * 1024.0));
  };
  std::vector<uint32_t> codes(count), order(count), codesOut(count), orderOut(count);
  for (size_t t = 0; t < count; ++t) {
    const Vec3 p = centroids[t];
    codes[t] = SpreadBits(quantize(p.x, low.x, high.x)) |
               (SpreadBits(quantize(p.y, low.y, high.y)) << 1) |
               (SpreadBits(quantize(p.z, low.z, high.z)) << 2);
    order[t] = static_cast<uint32_t>(t);
  }
  centroids = {};
  // Stable LSD radix sort, three passes of 10 bits.
  for (int shift = 0; shift < 30; shift += 10) {
    std::vector<uint32_t> starts(1025, 0);
    for (size_t i = 0; i < count; ++i) ++starts[((codes[i] >> shift) & 1023U) + 1];
    for (size_t b = 1; b < starts.size(); ++b) starts[b] += starts[b - 1];
    for (size_t i = 0; i < count; ++i) {
      const uint32_t slot = starts[(codes[i] >> shift) & 1023U]++;
      codesOut[slot] = codes[i];
      orderOut[slot] = order[i];
    }
    codes.swap(codesOut);
    order.swap(orderOut);
  }
  return order;
}

// A cluster's triangles [first, end) reordered so that each run of
// kGroupTriangles is compact: halved at the median centroid along the
// longest side of their box, recursively (the halves' sizes multiples of a group).
void SplitIntoGroups(const Scene& scene, uint32_t* first, uint32_t* end) {
  const size_t count = static_cast<size_t>(end - first);
  if (count <= SceneClusters::kGroupTriangles) return;
  auto centroid = [&](uint32_t t) {
    const auto& v = scene.triangles[t].vertices;
    return scene.verticesWorld[v[0]] + scene.verticesWorld[v[1]] + scene.verticesWorld[v[2]];
  };
  Vec3 low = centroid(*first), high = low;
  for (const uint32_t* t = first; t != end; ++t) {
    const Vec3 p = centroid(*t);
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const Vec3 size = high - low;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  auto key = [&](uint32_t t) {
    const Vec3 p = centroid(t);
    return axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
  };
  constexpr size_t kGroup = SceneClusters::kGroupTriangles;
  uint32_t* const middle = first + kGroup * ((count + 2 * kGroup - 1) / (2 * kGroup));
  // NaN after every number, ties by index: a strict order, the same split on every machine.
  std::nth_element(first, middle, end, [&](uint32_t a, uint32_t b) {
    const double ka = key(a), kb = key(b);
    const bool nanA = std::isnan(ka), nanB = std::isnan(kb);
    if (nanA != nanB) return nanB;
    if (!nanA && ka != kb) return ka < kb;
    return a < b;
  });
  SplitIntoGroups(scene, first, middle);
  SplitIntoGroups(scene, middle, end);
}

// A group's sphere in float: the center rounded, the radius measured from
// the rounded center in double and rounded up, so every corner is inside.
ClusterGroup FitGroup(const Scene& scene, std::span<const uint32_t> members) {
  SceneCluster sphere;
  FitSphere(scene, members, sphere);
  ClusterGroup g;
  g.center[0] = static_cast<float>(sphere.centerWorld.x);
  g.center[1] = static_cast<float>(sphere.centerWorld.y);
  g.center[2] = static_cast<float>(sphere.centerWorld.z);
  const Vec3 center{g.center[0], g.center[1], g.center[2]};
  double radius = 0.0;
  for (const uint32_t t : members) {
    for (const uint32_t v : scene.triangles[t].vertices) {
      radius = std::max(radius, Length(scene.verticesWorld[v] - center));
    }
  }
  const double padded = radius * (1.0 + 1e-9) + 1e-30;
  g.radius = static_cast<float>(padded);
  if (static_cast<double>(g.radius) < padded) g.radius = std::nextafter(g.radius, INFINITY);
  return g;
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
  out.groups.reserve(triangleCount / SceneClusters::kGroupTriangles + 1);
  out.corners.resize(triangleCount);
  std::vector<uint32_t> local(scene.verticesWorld.size(), UINT32_MAX);
  std::vector<uint32_t> distinct;
  for (size_t t = 0; t < triangleCount; t += SceneClusters::kMaxTriangles) {
    SceneCluster c;
    c.first = static_cast<uint32_t>(t);
    c.end = static_cast<uint32_t>(std::min(triangleCount, t + SceneClusters::kMaxTriangles));
    if (!out.sceneOrder) {
      SplitIntoGroups(scene, out.triangles.data() + c.first, out.triangles.data() + c.end);
    }
    const std::span<const uint32_t> members = out.Of(c);
    // Its distinct vertices, and each corner as an index among them.
    c.vertexFirst = static_cast<uint32_t>(out.positions.size());
    distinct.clear();
    for (uint32_t i = c.first; i < c.end; ++i) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = scene.triangles[out.triangles[i]].vertices[k];
        if (local[v] == UINT32_MAX) {
          local[v] = static_cast<uint32_t>(distinct.size());
          distinct.push_back(v);
          out.positions.push_back(scene.verticesWorld[v]);
        }
        out.corners[i][k] = static_cast<uint8_t>(local[v]);
      }
    }
    c.vertexEnd = static_cast<uint32_t>(out.positions.size());
    for (const uint32_t v : distinct) local[v] = UINT32_MAX;
    FitSphere(scene, members, c);
    FitCone(scene, members, c);
    for (size_t g = 0; g < members.size(); g += SceneClusters::kGroupTriangles) {
      out.groups.push_back(FitGroup(
          scene, members.subspan(g, std::min<size_t>(SceneClusters::kGroupTriangles,
                                                     members.size() - g))));
    }
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
