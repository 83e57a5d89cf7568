#include "geometry/FirstOccurrence.h"

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "geometry/FirstUseOrder.h"
#include "geometry/WeldVertices.h"
#include "io/scenes/SceneGenerators.h"

namespace termshade {
namespace {

// Keys of 3 floats drawn from a few values, so most repeat; -0 and +0 and
// two NaN payloads included: equality is bitwise, as meshoptimizer's.
std::vector<std::array<float, 3>> RepeatingKeys(size_t count, unsigned seed) {
  float nanA = std::numeric_limits<float>::quiet_NaN(), nanB;
  uint32_t bits;
  std::memcpy(&bits, &nanA, 4);
  bits ^= 1;
  std::memcpy(&nanB, &bits, 4);
  const float values[] = {0.0F, -0.0F, 1.0F, 1.5F, -2.0F, nanA, nanB, 1e-30F};
  std::mt19937 random(seed);
  std::vector<std::array<float, 3>> keys(count);
  for (auto& key : keys) {
    for (float& value : key) value = values[random() % 8];
  }
  return keys;
}

// Keys of 3 floats with about count / 3 distinct ones: the table must grow
// many times from a one-key start.
std::vector<std::array<float, 3>> MostlyDistinctKeys(size_t count, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<std::array<float, 3>> keys(count);
  const auto distinct = static_cast<uint32_t>(std::max<size_t>(1, count / 3));
  for (auto& key : keys) {
    const uint32_t k = static_cast<uint32_t>(random()) % distinct;
    key = {static_cast<float>(k), 0.5F * static_cast<float>(k % 7), -1.0F};
  }
  return keys;
}

// first[i] of every key is the first key bitwise equal to it, as
// meshoptimizer's remap numbers them, whatever size the table starts at.
void ExpectFirstOccurrencesMatchRemap(const std::vector<std::array<float, 3>>& keys,
                                      size_t expectedDistinct) {
  const size_t count = keys.size();
  std::vector<unsigned int> remap(count);
  meshopt_generateVertexRemap(remap.data(), nullptr, count, keys.data(), count, sizeof keys[0]);
  std::vector<uint32_t> firstOfRemap(count, UINT32_MAX);
  for (size_t i = 0; i < count; ++i) {
    if (firstOfRemap[remap[i]] == UINT32_MAX) firstOfRemap[remap[i]] = static_cast<uint32_t>(i);
  }
  std::vector<uint32_t> first(count, 12345);
  FindFirstOccurrences<12>(
      count, [&](size_t i) { return reinterpret_cast<const char*>(keys[i].data()); }, first.data(),
      expectedDistinct);
  for (size_t i = 0; i < count; ++i) {
    ASSERT_EQ(first[i], firstOfRemap[remap[i]]) << "key " << i << " of " << count;
  }
}

TEST(FirstOccurrence, GrowingTableMatchesMeshoptimizersRemap) {
  for (const size_t count : {1UL, 100UL, 5000UL, 300000UL}) {
    for (const size_t expectedDistinct : {1UL, 64UL, count}) {
      ExpectFirstOccurrencesMatchRemap(MostlyDistinctKeys(count, static_cast<unsigned>(count)),
                                       expectedDistinct);
    }
  }
}

TEST(FirstOccurrence, MatchesMeshoptimizersRemap) {
  for (const size_t count : {1UL, 7UL, 300UL, 100000UL}) {
    ExpectFirstOccurrencesMatchRemap(RepeatingKeys(count, static_cast<unsigned>(count)), 0);
  }
}

// A mesh with repeated positions, unused vertices and segments.
Mesh UnweldedWithExtras(unsigned seed) {
  const Mesh sphere = GenerateSphere(20, 24);
  std::mt19937 random(seed);
  Mesh mesh;
  mesh.verticesFile.push_back({9, 9, 9});  // unused
  for (size_t f = 0; f < sphere.FaceCount(); ++f) {
    std::vector<uint32_t> corners;
    for (const uint32_t v : sphere.Face(f)) {
      if (random() % 3 == 0) mesh.verticesFile.push_back({-1, -1, -1});  // unused
      corners.push_back(static_cast<uint32_t>(mesh.verticesFile.size()));
      mesh.verticesFile.push_back(sphere.verticesFile[v]);
    }
    mesh.AddFace(corners);
  }
  mesh.verticesFile.push_back({0, 0, -0.0});
  mesh.verticesFile.push_back({0, 0, 0.0});
  const auto last = static_cast<uint32_t>(mesh.verticesFile.size() - 1);
  mesh.segments.push_back({last - 1, last});
  mesh.segments.push_back({last, 3});
  return mesh;
}

TEST(WeldAndNumberByFirstUse, EqualsWeldingThenNumberingByFirstUse) {
  for (const unsigned seed : {1U, 2U, 3U}) {
    Mesh expected = UnweldedWithExtras(seed);
    Mesh actual = expected;
    WeldExactPositions(expected);
    NumberVerticesByFirstUse(expected);
    WeldAndNumberByFirstUse(actual);
    ASSERT_EQ(actual.faceCorners, expected.faceCorners);
    ASSERT_EQ(actual.segments, expected.segments);
    ASSERT_EQ(actual.verticesFile.size(), expected.verticesFile.size());
    EXPECT_EQ(std::memcmp(actual.verticesFile.data(), expected.verticesFile.data(),
                          actual.verticesFile.size() * sizeof(Vec3)),
              0);
  }
}

}  // namespace
}  // namespace termshade
