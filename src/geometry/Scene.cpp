#include "geometry/Scene.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "geometry/EdgeAdjacency.h"
#include "geometry/FaceNormal.h"
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

void AddFaceGeometry(Scene& scene, size_t face, std::vector<Vec3>& cornersScratch,
                     std::vector<CornerTriangle>& trianglesScratch) {
  const auto corners = scene.mesh.Face(face);
  cornersScratch.clear();
  bool finite = true;
  for (uint32_t v : corners) {
    cornersScratch.push_back(scene.verticesWorld[v]);
    finite = finite && IsFinite(scene.verticesWorld[v]);
  }
  // Normal and plane through the mean corner (exact for planar faces,
  // a least-squares-like compromise for slightly non-planar ones).
  const Vec3 normal = finite ? Normalized(NewellNormal(cornersScratch)) : Vec3{};
  Vec3 mean;
  for (const Vec3& p : cornersScratch) mean = mean + p;
  mean = mean * (1.0 / static_cast<double>(std::max<size_t>(1, cornersScratch.size())));
  scene.facePlanesWorld.push_back({normal, finite ? Dot(normal, mean) : 0.0});

  trianglesScratch.clear();
  if (finite) TriangulatePolygon(cornersScratch, trianglesScratch);
  for (const CornerTriangle& t : trianglesScratch) {
    scene.triangles.push_back(
        {{corners[t[0]], corners[t[1]], corners[t[2]]}, static_cast<uint32_t>(face)});
  }
  scene.faceTriangleStarts.push_back(static_cast<uint32_t>(scene.triangles.size()));
}

// Unique undirected edges in (low, high) order, each with the first face that
// has it; an edge is hidden when any face that has it hides it.
void CollectEdges(Scene& scene, const EdgeAdjacency& adjacency) {
  adjacency.ForEachEdge([&scene](uint32_t low, std::span<const EdgeUse> uses) {
    const bool hidden =
        std::any_of(uses.begin(), uses.end(), [](const EdgeUse& use) { return use.hidden; });
    if (!hidden) scene.edges.push_back({{low, uses[0].highVertex}, uses[0].face});
  });
  for (const auto& segment : scene.mesh.segments) scene.edges.push_back({segment, UINT32_MAX});
}

// Closed (every edge used once each way), connected, and convex at every
// edge (each face's corners lie on or behind its neighbour's plane): a convex
// solid, where facing decides visibility.
bool IsConvexClosedSolid(const Scene& scene, const EdgeAdjacency& adjacency) {
  const Mesh& mesh = scene.mesh;
  const size_t faceCount = mesh.FaceCount();
  if (faceCount < 4 || scene.triangles.empty()) return false;
  std::vector<uint32_t> component(faceCount);
  for (uint32_t f = 0; f < faceCount; ++f) component[f] = f;
  auto root = [&](uint32_t f) {
    while (component[f] != f) f = component[f] = component[component[f]];
    return f;
  };
  const double tolerance = 1e-9 * std::max(1.0, scene.diagonalModelUnits);
  auto behindPlane = [&](uint32_t f, uint32_t g) {
    const FacePlane& plane = scene.facePlanesWorld[f];
    if (plane.normal == Vec3{}) return false;
    for (uint32_t v : mesh.Face(g)) {
      if (Dot(plane.normal, scene.verticesWorld[v]) - plane.offset > tolerance) return false;
    }
    return true;
  };
  bool convex = true;
  adjacency.ForEachEdge([&](uint32_t, std::span<const EdgeUse> uses) {
    if (!convex) return;
    if (uses.size() != 2 || uses[0].forward == uses[1].forward) {
      convex = false;  // open, non-manifold or inconsistently wound
      return;
    }
    const uint32_t f = uses[0].face, g = uses[1].face;
    component[root(f)] = root(g);
    convex = behindPlane(f, g) && behindPlane(g, f);
  });
  if (!convex) return false;
  for (uint32_t f = 0; f < faceCount; ++f) {
    if (root(f) != root(0)) return false;
  }
  return true;
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

  // Step 3: per-face normal, plane and triangles.
  std::vector<Vec3> cornersScratch;
  std::vector<CornerTriangle> trianglesScratch;
  scene.faceTriangleStarts.push_back(0);
  for (size_t face = 0; face < scene.mesh.FaceCount(); ++face) {
    AddFaceGeometry(scene, face, cornersScratch, trianglesScratch);
  }
  CollectEdges(scene, *adjacency);
  scene.clusters = BuildClusters(scene);
  scene.convexClosedSolid = IsConvexClosedSolid(scene, *adjacency);
  return scene;
}

}  // namespace termshade
