#include "geometry/DuplicateTriangles.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <unordered_set>

#include "geometry/Scene.h"

#include <meshoptimizer.h>

namespace termshade {
namespace {

// The triangle's corners rotated so the smallest comes first (the same
// triangle in the same turn gives the same key).
std::array<uint32_t, 3> RotatedKey(const uint32_t* t) {
  if (t[1] < t[0] && t[1] <= t[2]) return {t[1], t[2], t[0]};
  if (t[2] < t[0] && t[2] < t[1]) return {t[2], t[0], t[1]};
  return {t[0], t[1], t[2]};
}

struct KeyHash {
  size_t operator()(const std::array<uint32_t, 3>& key) const {
    uint64_t h = key[0];
    h = h * 0x9E3779B97F4A7C15ULL ^ key[1];
    h = h * 0x9E3779B97F4A7C15ULL ^ key[2];
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

// Per triangle, whether it repeats an earlier one; empty (none dropped) once
// more than kMostDistinctTriangles differ: the input is then not mainly
// repeats, and the table's memory stays bounded (about 40 MB).
std::vector<uint8_t> RepeatedTriangles(const uint32_t* indices, size_t triangleCount,
                                       size_t& repeated) {
  constexpr size_t kMostDistinctTriangles = size_t{1} << 20;
  std::unordered_set<std::array<uint32_t, 3>, KeyHash> seen;
  std::vector<uint8_t> drop(triangleCount, 0);
  repeated = 0;
  for (size_t t = 0; t < triangleCount; ++t) {
    if (seen.insert(RotatedKey(indices + 3 * t)).second) {
      if (seen.size() > kMostDistinctTriangles) {
        repeated = 0;
        return {};
      }
    } else {
      drop[t] = 1;
      ++repeated;
    }
  }
  return drop;
}

// The triangles' corners, each vertex replaced by the first vertex at its
// position (meshoptimizer's shadow index buffer, bit-exact positions).
std::vector<uint32_t> PositionJoinedCorners(const Scene& scene) {
  const size_t cornerCount = 3 * scene.triangles.size();
  std::vector<uint32_t> joined(cornerCount);
  meshopt_generateShadowIndexBuffer(joined.data(), scene.triangles.front().vertices.data(),
                                    cornerCount, scene.verticesWorld.data(),
                                    scene.verticesWorld.size(), sizeof(Vec3), sizeof(Vec3));
  return joined;
}

// How many distinct vertices of vertexCount the corners use.
size_t DistinctCount(const std::vector<uint32_t>& corners, size_t vertexCount) {
  std::vector<bool> used(vertexCount, false);
  size_t count = 0;
  for (const uint32_t v : corners) {
    if (!used[v]) ++count;
    used[v] = true;
  }
  return count;
}

}  // namespace

size_t DropRepeatedTriangles(std::vector<uint32_t>& indices, std::vector<uint32_t>* faces) {
  const size_t triangleCount = indices.size() / 3;
  size_t repeated = 0;
  const std::vector<uint8_t> drop = RepeatedTriangles(indices.data(), triangleCount, repeated);
  if (repeated == 0) return 0;
  size_t kept = 0;
  for (size_t t = 0; t < triangleCount; ++t) {
    if (drop[t] != 0) continue;
    std::copy_n(indices.begin() + static_cast<std::ptrdiff_t>(3 * t), 3,
                indices.begin() + static_cast<std::ptrdiff_t>(3 * kept));
    if (faces != nullptr) (*faces)[kept] = (*faces)[t];
    ++kept;
  }
  indices.resize(3 * kept);
  if (faces != nullptr) faces->resize(kept);
  return repeated;
}

size_t DropRepeatedSceneTriangles(Scene& scene, size_t faceCount) {
  const size_t triangleCount = scene.triangles.size();
  if (triangleCount == 0) return 0;
  static_assert(sizeof(SceneTriangle) == 3 * sizeof(uint32_t));
  const uint32_t* keys = scene.triangles.front().vertices.data();
  std::vector<uint32_t> joined;
  if (triangleCount <= kRepeatCheckTrianglesPerVertex * scene.verticesWorld.size()) {
    // Few triangles a vertex: repeats only where the mesh is unwelded (each
    // triangle its own corners, as a .dat may be): compared by position there.
    if (2 * scene.verticesWorld.size() < 5 * triangleCount) return 0;
    joined = PositionJoinedCorners(scene);
    if (triangleCount <=
        kRepeatCheckTrianglesPerVertex * DistinctCount(joined, scene.verticesWorld.size()))
      return 0;
    keys = joined.data();
  }
  size_t repeated = 0;
  const std::vector<uint8_t> drop = RepeatedTriangles(keys, triangleCount, repeated);
  if (repeated == 0) return 0;
  // The maps between faces and triangles made explicit, then compacted.
  if (scene.faceTriangleStarts.empty()) {
    scene.faceTriangleStarts.resize(faceCount + 1);
    std::iota(scene.faceTriangleStarts.begin(), scene.faceTriangleStarts.end(), 0U);
    scene.triangleFaces.resize(triangleCount);
    std::iota(scene.triangleFaces.begin(), scene.triangleFaces.end(), 0U);
  }
  size_t kept = 0;
  size_t face = 0;
  for (size_t t = 0; t < triangleCount; ++t) {
    while (face <= faceCount && scene.faceTriangleStarts[face] <= t) {
      scene.faceTriangleStarts[face++] = static_cast<uint32_t>(kept);
    }
    if (drop[t] != 0) continue;
    scene.triangles[kept] = scene.triangles[t];
    scene.triangleFaces[kept] = scene.triangleFaces[t];
    ++kept;
  }
  while (face <= faceCount) scene.faceTriangleStarts[face++] = static_cast<uint32_t>(kept);
  scene.triangles.resize(kept);
  scene.triangleFaces.resize(kept);
  return repeated;
}

}  // namespace termshade
