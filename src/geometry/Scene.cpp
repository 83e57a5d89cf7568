#include "geometry/Scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "geometry/EdgeAdjacency.h"
#include "geometry/FaceNormal.h"
#include "geometry/HugePages.h"
#include "geometry/OutwardOrientation.h"
#include "geometry/Triangulate.h"

namespace termshade {
namespace {

struct Bounds {
  Vec3 low{INFINITY, INFINITY, INFINITY};
  Vec3 high{-INFINITY, -INFINITY, -INFINITY};

  void Add(Vec3 p) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  bool Empty() const { return !(low.x <= high.x); }
};

Bounds FiniteBounds(const std::vector<Vec3>& points) {
  Bounds bounds;
  for (const Vec3& p : points) {
    if (IsFinite(p)) bounds.Add(p);
  }
  return bounds;
}

// The face's plane through its mean corner (exact for planar faces, a
// least-squares-like compromise for slightly non-planar ones); zero when a
// corner is not finite.
FacePlane PlaneOfFace(const Scene& scene, size_t face) {
  const auto corners = scene.mesh.Face(face);
  const auto pointAt = [&](size_t i) { return scene.verticesWorld[corners[i]]; };
  bool finite = true;
  Vec3 mean;
  for (size_t i = 0; i < corners.size(); ++i) {
    finite = finite && IsFinite(pointAt(i));
    mean = mean + pointAt(i);
  }
  mean = mean * (1.0 / static_cast<double>(std::max<size_t>(1, corners.size())));
  const Vec3 normal = finite ? Normalized(NewellNormal(corners.size(), pointAt)) : Vec3{};
  return {normal, finite ? Dot(normal, mean) : 0.0};
}

// The face's triangles, none when a corner is not finite.
void AddFaceTriangles(Scene& scene, size_t face, std::vector<Vec3>& cornersScratch,
                      std::vector<CornerTriangle>& trianglesScratch) {
  const auto corners = scene.mesh.Face(face);
  trianglesScratch.clear();
  cornersScratch.clear();
  bool finite = true;
  for (uint32_t v : corners) {
    cornersScratch.push_back(scene.verticesWorld[v]);
    finite = finite && IsFinite(scene.verticesWorld[v]);
  }
  if (finite) TriangulatePolygon(cornersScratch, trianglesScratch);
  for (const CornerTriangle& t : trianglesScratch) {
    scene.triangles.push_back(
        {{corners[t[0]], corners[t[1]], corners[t[2]]}, static_cast<uint32_t>(face)});
  }
  scene.faceTriangleStarts.push_back(static_cast<uint32_t>(scene.triangles.size()));
}

// Closed (every edge used once each way) and connected: the two faces of
// each edge, or nullopt when the mesh is not such a surface (or has under 4
// faces). The pairs let the edge uses be freed before the planes are built.
std::optional<std::vector<std::array<uint32_t, 2>>> ClosedSurfaceFacePairs(
    const Mesh& mesh, const EdgeAdjacency& adjacency) {
  const size_t faceCount = mesh.FaceCount();
  if (faceCount < 4) return std::nullopt;
  std::vector<uint32_t> component(faceCount);
  for (uint32_t f = 0; f < faceCount; ++f) component[f] = f;
  auto root = [&](uint32_t f) {
    while (component[f] != f) f = component[f] = component[component[f]];
    return f;
  };
  std::vector<std::array<uint32_t, 2>> pairs;
  pairs.reserve(adjacency.UseCount() / 2);
  AdviseHugePages(pairs);
  bool closed = true;
  adjacency.ForEachEdge([&](uint32_t, std::span<const EdgeUse> uses) {
    if (!closed) return;
    if (uses.size() != 2 || uses[0].forward == uses[1].forward) {
      closed = false;  // open, non-manifold or inconsistently wound
      return;
    }
    const uint32_t f = uses[0].face, g = uses[1].face;
    component[root(f)] = root(g);
    pairs.push_back({f, g});
  });
  if (!closed) return std::nullopt;
  for (uint32_t f = 0; f < faceCount; ++f) {
    if (root(f) != root(0)) return std::nullopt;
  }
  return pairs;
}

// Convex at every edge: each face's corners lie on or behind its neighbour's
// plane. With a closed connected surface, a convex solid, where facing
// decides visibility.
bool ConvexAtEveryEdge(const Scene& scene, std::span<const std::array<uint32_t, 2>> facePairs) {
  const double tolerance = 1e-9 * std::max(1.0, scene.diagonalModelUnits);
  auto behindPlane = [&](uint32_t f, uint32_t g) {
    const FacePlane& plane = scene.facePlanesWorld[f];
    if (plane.normal == Vec3{}) return false;
    for (uint32_t v : scene.mesh.Face(g)) {
      if (Dot(plane.normal, scene.verticesWorld[v]) - plane.offset > tolerance) return false;
    }
    return true;
  };
  return std::all_of(facePairs.begin(), facePairs.end(), [&](const std::array<uint32_t, 2>& pair) {
    return behindPlane(pair[0], pair[1]) && behindPlane(pair[1], pair[0]);
  });
}

}  // namespace

Scene PrepareScene(Mesh mesh, std::optional<UpAxis> upOverride) {
  Scene scene;
  scene.name = mesh.name;
  scene.mesh = std::move(mesh);
  scene.upAxis = upOverride.value_or(scene.mesh.upAxisFile);
  scene.upAxisOverridden = upOverride.has_value();

  // Step 1: world space is file space turned up (+z), centered on the bounding box.
  scene.verticesWorld.reserve(scene.mesh.verticesFile.size());
  AdviseHugePages(scene.verticesWorld);
  for (const Vec3& p : scene.mesh.verticesFile) {
    scene.verticesWorld.push_back(ZUpFromFile(scene.upAxis, p));
  }
  const Bounds bounds = FiniteBounds(scene.verticesWorld);
  const Vec3 center = bounds.Empty() ? Vec3{} : (bounds.low + bounds.high) * 0.5;
  scene.worldFromFile = Mat4::Translation(-center) * ZUpFromFile(scene.upAxis);
  scene.diagonalModelUnits = bounds.Empty() ? 0.0 : Length(bounds.high - bounds.low);
  for (Vec3& p : scene.verticesWorld) {
    const bool finite = IsFinite(p);
    p = p - center;
    if (finite) scene.radiusModelUnits = std::max(scene.radiusModelUnits, Length(p));
  }

  // Step 2: inside-out closed parts turned outward, once.
  std::optional<EdgeAdjacency> adjacency(std::in_place, scene.mesh);
  scene.facesTurnedOutward = OrientClosedPartsOutward(scene.mesh, *adjacency, scene.verticesWorld);
  if (scene.facesTurnedOutward > 0) adjacency.emplace(scene.mesh);

  // Step 3: whether the model is a closed connected surface; the edge uses
  // are freed before the planes and triangles take their place.
  auto facePairs = ClosedSurfaceFacePairs(scene.mesh, *adjacency);
  adjacency.reset();

  // Step 4: per-face planes, then whether the surface is convex at every edge.
  const size_t faceCount = scene.mesh.FaceCount();
  scene.facePlanesWorld.reserve(faceCount);
  AdviseHugePages(scene.facePlanesWorld);
  for (size_t face = 0; face < faceCount; ++face) {
    scene.facePlanesWorld.push_back(PlaneOfFace(scene, face));
  }
  const bool convex = facePairs && ConvexAtEveryEdge(scene, *facePairs);
  facePairs.reset();

  // Step 5: per-face triangles (a face of n corners gives at most n - 2).
  const size_t cornerCount = scene.mesh.faceCorners.size();
  scene.triangles.reserve(cornerCount - std::min(cornerCount, 2 * faceCount));
  scene.faceTriangleStarts.reserve(faceCount + 1);
  AdviseHugePages(scene.triangles);
  AdviseHugePages(scene.faceTriangleStarts);
  scene.faceTriangleStarts.push_back(0);
  std::vector<Vec3> cornersScratch;
  std::vector<CornerTriangle> trianglesScratch;
  for (size_t face = 0; face < faceCount; ++face) {
    AddFaceTriangles(scene, face, cornersScratch, trianglesScratch);
  }
  scene.clusters = BuildClusters(scene);
  scene.convexClosedSolid = convex && !scene.triangles.empty();
  return scene;
}

}  // namespace termshade
