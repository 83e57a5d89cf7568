#include "geometry/Scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "geometry/FaceNormal.h"
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

// Unique undirected edges; an edge is hidden when any face that has it hides it.
void CollectEdges(Scene& scene) {
  std::map<std::pair<uint32_t, uint32_t>, std::pair<uint32_t, bool>> edgeFaceHidden;
  const Mesh& mesh = scene.mesh;
  for (size_t face = 0; face < mesh.FaceCount(); ++face) {
    const auto corners = mesh.Face(face);
    for (size_t i = 0; i < corners.size(); ++i) {
      const uint32_t a = corners[i], b = corners[(i + 1) % corners.size()];
      if (a == b) continue;
      const bool hidden = mesh.edgeHidden[mesh.faceStarts[face] + i] != 0;
      auto [it, inserted] = edgeFaceHidden.try_emplace({std::min(a, b), std::max(a, b)},
                                                       static_cast<uint32_t>(face), hidden);
      if (!inserted) it->second.second = it->second.second || hidden;
    }
  }
  for (const auto& [key, value] : edgeFaceHidden) {
    if (!value.second) scene.edges.push_back({{key.first, key.second}, value.first});
  }
  for (const auto& segment : mesh.segments) scene.edges.push_back({segment, UINT32_MAX});
}

// Closed (every directed edge has its reverse in exactly one other face),
// connected, and convex at every edge (each face's corners lie on or behind
// its neighbours' planes): a convex solid, where facing decides visibility.
bool IsConvexClosedSolid(const Scene& scene) {
  const Mesh& mesh = scene.mesh;
  const size_t faceCount = mesh.FaceCount();
  if (faceCount < 4 || scene.triangles.empty()) return false;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> faceOfEdge;
  for (uint32_t f = 0; f < faceCount; ++f) {
    const auto corners = mesh.Face(f);
    for (size_t i = 0; i < corners.size(); ++i) {
      if (!faceOfEdge.try_emplace({corners[i], corners[(i + 1) % corners.size()]}, f).second) {
        return false;  // an edge used twice the same way
      }
    }
  }
  std::vector<uint32_t> component(faceCount);
  for (uint32_t f = 0; f < faceCount; ++f) component[f] = f;
  auto root = [&](uint32_t f) {
    while (component[f] != f) f = component[f] = component[component[f]];
    return f;
  };
  const double tolerance = 1e-9 * std::max(1.0, scene.diagonalModelUnits);
  for (const auto& [edge, f] : faceOfEdge) {
    const auto twin = faceOfEdge.find({edge.second, edge.first});
    if (twin == faceOfEdge.end()) return false;
    const uint32_t g = twin->second;
    component[root(f)] = root(g);
    const Vec3 n = scene.facePlanesWorld[f].normal;
    if (n == Vec3{}) return false;
    for (uint32_t v : mesh.Face(g)) {
      if (Dot(n, scene.verticesWorld[v]) - scene.facePlanesWorld[f].offset > tolerance)
        return false;
    }
  }
  for (uint32_t f = 0; f < faceCount; ++f) {
    if (root(f) != root(0)) return false;
  }
  return true;
}

}  // namespace

Scene PrepareScene(Mesh mesh) {
  Scene scene;
  scene.name = mesh.name;
  scene.mesh = std::move(mesh);

  // Step 1: world space is file space centered on the bounding box.
  const Bounds bounds = FiniteBounds(scene.mesh.verticesFile);
  const Vec3 center = bounds.Empty() ? Vec3{} : (bounds.low + bounds.high) * 0.5;
  scene.worldFromFile = Mat4::Translation(-center);
  scene.diagonalModelUnits = bounds.Empty() ? 0.0 : Length(bounds.high - bounds.low);
  scene.verticesWorld.reserve(scene.mesh.verticesFile.size());
  for (const Vec3& p : scene.mesh.verticesFile) {
    scene.verticesWorld.push_back(p - center);
    if (IsFinite(p)) {
      scene.radiusModelUnits = std::max(scene.radiusModelUnits, Length(scene.verticesWorld.back()));
    }
  }

  // Step 2: per-face normal, plane and triangles.
  std::vector<Vec3> cornersScratch;
  std::vector<CornerTriangle> trianglesScratch;
  scene.faceTriangleStarts.push_back(0);
  for (size_t face = 0; face < scene.mesh.FaceCount(); ++face) {
    AddFaceGeometry(scene, face, cornersScratch, trianglesScratch);
  }
  CollectEdges(scene);
  scene.convexClosedSolid = IsConvexClosedSolid(scene);
  return scene;
}

}  // namespace termshade
