#include "geometry/FaceUv.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

}  // namespace

std::array<double, 2> FaceUvAt(const Scene& scene, uint32_t face, Vec3 p) {
  const FacePlane& plane = scene.facePlanesWorld[face];
  double bestLeast = -std::numeric_limits<double>::infinity();
  std::array<double, 2> best{0.0, 0.0};
  const uint32_t end = scene.FaceTrianglesBegin(face + 1);
  for (uint32_t t = scene.FaceTrianglesBegin(face); t < end; ++t) {
    const auto& v = scene.triangles[t].vertices;
    const auto w = Barycentric(p, scene.verticesWorld[v[0]], scene.verticesWorld[v[1]],
                               scene.verticesWorld[v[2]], plane.normal);
    const double least = std::min({w[0], w[1], w[2]});
    if (!(least > bestLeast)) continue;
    bestLeast = least;
    best = {0.0, 0.0};
    for (int k = 0; k < 3; ++k) {
      const auto uv = scene.textures.UvAt(face, v[k]);
      best[0] += w[k] * uv[0];
      best[1] += w[k] * uv[1];
    }
    if (least >= 0.0) break;
  }
  return best;
}


}  // namespace termshade
