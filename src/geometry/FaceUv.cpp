#include "geometry/FaceUv.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace termshade {
namespace {

// Barycentric weights of p in triangle (a, b, c) about the normal.
std::array<double, 3> Barycentric(Vec3 p, Vec3 a, Vec3 b, Vec3 c, Vec3 normal) {
  const double whole = Dot(normal, Cross(b - a, c - a));
  if (whole == 0.0 || !std::isfinite(whole)) return {1.0, 0.0, 0.0};
  const double wa = Dot(normal, Cross(b - p, c - p)) / whole;
  const double wb = Dot(normal, Cross(c - p, a - p)) / whole;
  return {wa, wb, 1.0 - wa - wb};
}

// Least squares of t = a x + b y + d over a face's corners in plane coordinates
// (x, y), solved by Cramer's rule; the mean where the corners are degenerate.
std::array<double, 3> FitPlaneMap(const std::vector<std::array<double, 3>>& points) {
  double m[3][3] = {}, r[3] = {};
  for (const auto& [x, y, t] : points) {
    const double row[3] = {x, y, 1.0};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
      r[i] += row[i] * t;
    }
  }
  const auto det = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double whole = det(m);
  if (!(std::fabs(whole) > 1e-300)) return {0.0, 0.0, points.empty() ? 0.0 : r[2] / m[2][2]};
  std::array<double, 3> solution{};
  for (int k = 0; k < 3; ++k) {
    double swapped[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) swapped[i][j] = j == k ? r[i] : m[i][j];
    }
    solution[static_cast<size_t>(k)] = det(swapped) / whole;
  }
  return solution;
}

// The affine map of a big face: its corners' coordinates fitted over its plane.
SceneTextures::AffineUv FitFace(const Scene& scene, uint32_t face) {
  const SceneTextures& t = scene.textures;
  const Vec3 normal = scene.facePlanesWorld[face].normal;
  // Step 1: a basis of the plane, and the corners in it about their mean.
  const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 e1 = Normalized(Cross(normal, helper)), e2 = Cross(normal, e1);
  Vec3 center;
  const uint32_t begin = t.uvStarts[face], end = t.uvStarts[face + 1];
  for (uint32_t at = begin; at < end; ++at) center = center + scene.verticesWorld[t.uvCorners[at]];
  center = center * (1.0 / std::max<uint32_t>(1, end - begin));
  std::vector<std::array<double, 3>> us, vs;
  for (uint32_t at = begin; at < end; ++at) {
    const Vec3 d = scene.verticesWorld[t.uvCorners[at]] - center;
    us.push_back({Dot(e1, d), Dot(e2, d), t.cornerUvs[at][0]});
    vs.push_back({Dot(e1, d), Dot(e2, d), t.cornerUvs[at][1]});
  }
  // Step 2: the two fits, turned back into maps of world points.
  const auto u = FitPlaneMap(us), v = FitPlaneMap(vs);
  SceneTextures::AffineUv map;
  map.uFromPoint = e1 * u[0] + e2 * u[1];
  map.vFromPoint = e1 * v[0] + e2 * v[1];
  map.uOffset = u[2] - Dot(map.uFromPoint, center);
  map.vOffset = v[2] - Dot(map.vFromPoint, center);
  return map;
}

}  // namespace

void BuildFaceUvs(Scene& scene) {
  SceneTextures& t = scene.textures;
  if (!t.Any()) return;
  t.triangleUvs.assign(scene.triangles.size(), std::array<float, 6>{});
  std::vector<std::pair<uint32_t, std::array<float, 2>>> sorted;
  for (uint32_t face = 0; face < scene.FaceCount(); ++face) {
    if (t.faceTextures[face] == kNoTexture) continue;
    // Step 1: the face's corners by vertex, for a binary search per triangle corner.
    sorted.clear();
    for (uint32_t at = t.uvStarts[face]; at < t.uvStarts[face + 1]; ++at) {
      sorted.emplace_back(t.uvCorners[at], t.cornerUvs[at]);
    }
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    const uint32_t begin = scene.FaceTrianglesBegin(face), end = scene.FaceTrianglesBegin(face + 1);
    for (uint32_t tri = begin; tri < end; ++tri) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t vertex = scene.triangles[tri].vertices[static_cast<size_t>(k)];
        const auto at = std::lower_bound(sorted.begin(), sorted.end(), vertex,
                                         [](const auto& a, uint32_t v) { return a.first < v; });
        const std::array<float, 2> uv =
            at != sorted.end() && at->first == vertex ? at->second : std::array<float, 2>{};
        t.triangleUvs[tri][static_cast<size_t>(2 * k)] = uv[0];
        t.triangleUvs[tri][static_cast<size_t>(2 * k + 1)] = uv[1];
      }
    }
    // Step 2: a big face's affine map.
    if (end - begin > kMostScannedTriangles) t.bigFaceUvs.emplace(face, FitFace(scene, face));
  }
}

std::array<double, 2> FaceUvAt(const Scene& scene, uint32_t face, Vec3 p) {
  const SceneTextures& t = scene.textures;
  const uint32_t begin = scene.FaceTrianglesBegin(face), end = scene.FaceTrianglesBegin(face + 1);
  if (end - begin > kMostScannedTriangles) {
    if (const auto big = t.bigFaceUvs.find(face); big != t.bigFaceUvs.end()) {
      const SceneTextures::AffineUv& map = big->second;
      return {Dot(map.uFromPoint, p) + map.uOffset, Dot(map.vFromPoint, p) + map.vOffset};
    }
  }
  const FacePlane& plane = scene.facePlanesWorld[face];
  double bestLeast = -std::numeric_limits<double>::infinity();
  std::array<double, 2> best{0.0, 0.0};
  for (uint32_t tri = begin; tri < end; ++tri) {
    const auto& v = scene.triangles[tri].vertices;
    const auto w = Barycentric(p, scene.verticesWorld[v[0]], scene.verticesWorld[v[1]],
                               scene.verticesWorld[v[2]], plane.normal);
    const double least = std::min({w[0], w[1], w[2]});
    if (!(least > bestLeast)) continue;
    bestLeast = least;
    const auto& uv = t.triangleUvs[tri];
    best = {w[0] * uv[0] + w[1] * uv[2] + w[2] * uv[4], w[0] * uv[1] + w[1] * uv[3] + w[2] * uv[5]};
    if (least >= 0.0) break;
  }
  return best;
}

}  // namespace termshade
