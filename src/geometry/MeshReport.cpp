#include "geometry/MeshReport.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <tuple>
#include <vector>

namespace termshade {
namespace {

// Union-find over vertices, with path halving.
class VertexSets {
 public:
  explicit VertexSets(size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), uint32_t{0});
  }
  uint32_t Find(uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void Join(uint32_t a, uint32_t b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<uint32_t> parent_;
};

// Parts: faces joined through the vertices they share.
size_t CountParts(const Mesh& mesh) {
  VertexSets sets(mesh.verticesFile.size());
  std::vector<bool> used(mesh.verticesFile.size(), false);
  for (size_t face = 0; face < mesh.FaceCount(); ++face) {
    const auto corners = mesh.Face(face);
    for (const uint32_t corner : corners) {
      used[corner] = true;
      sets.Join(corners[0], corner);
    }
  }
  size_t parts = 0;
  for (uint32_t v = 0; v < used.size(); ++v) parts += used[v] && sets.Find(v) == v ? 1 : 0;
  return parts;
}

// Edges as sorted vertex pairs, counted by how many faces have them.
void CountEdges(const Mesh& mesh, MeshReport& report) {
  std::vector<uint64_t> edges;
  edges.reserve(mesh.faceCorners.size());
  for (size_t face = 0; face < mesh.FaceCount(); ++face) {
    const auto corners = mesh.Face(face);
    for (size_t i = 0; i < corners.size(); ++i) {
      const uint32_t a = corners[i], b = corners[(i + 1) % corners.size()];
      if (a == b) continue;  // a repeated corner is no edge
      edges.push_back(uint64_t{std::min(a, b)} << 32 | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t end = i + 1;
    while (end < edges.size() && edges[end] == edges[i]) ++end;
    report.openEdges += end - i == 1 ? 1 : 0;
    report.nonManifoldEdges += end - i >= 3 ? 1 : 0;
    i = end;
  }
}

size_t DistinctColours(std::vector<Rgb> colours) {
  std::sort(colours.begin(), colours.end(), [](const Rgb& a, const Rgb& b) {
    return std::tie(a.r, a.g, a.b) < std::tie(b.r, b.g, b.b);
  });
  return static_cast<size_t>(std::unique(colours.begin(), colours.end()) - colours.begin());
}

}  // namespace

MeshReport ReportMesh(const Mesh& mesh) {
  MeshReport report;
  report.vertices = mesh.verticesFile.size();
  report.faces = mesh.FaceCount();
  report.segments = mesh.segments.size();
  report.parts = CountParts(mesh);
  CountEdges(mesh, report);
  report.faceColours = DistinctColours(mesh.faceColors);
  // Bounds of the vertices faces or segments use.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  const auto include = [&](uint32_t v) {
    const Vec3& p = mesh.verticesFile[v];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  };
  for (const uint32_t corner : mesh.faceCorners) include(corner);
  for (const auto& segment : mesh.segments) {
    include(segment[0]);
    include(segment[1]);
  }
  if (lo.x <= hi.x) {
    report.boundsMin = lo;
    report.boundsMax = hi;
  }
  return report;
}

}  // namespace termshade
