#include "geometry/LevelOfDetail.h"

#include <meshoptimizer.h>

#include "geometry/DuplicateTriangles.h"
#include "geometry/FaceUv.h"
#include "process/ChildWork.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <tuple>
#include <utility>

namespace termshade {
namespace {

constexpr uint32_t kNone = UINT32_MAX;
// A fin: height over longest edge below kFinHeight, and a normal whose cosine
// with every source face at its corners is below kFinAgreement.
constexpr double kFinHeight = 0.05;
constexpr double kFinAgreement = 0.5;

// What every level is simplified from: float positions, indices that join
// vertices at the same position (so seams and unwelded files collapse too),
// and one face touching each such vertex.
struct Source {
  std::vector<float> positions;   ///< xyz per vertex of the exact scene
  std::vector<uint32_t> indices;  ///< 3 per exact triangle, position-joined
  std::vector<uint32_t> vertexFace;
  double scaleModelUnits = 0.0;  ///< meshoptimizer's extent: relative error x scale = model units
};

Source MakeSource(const Scene& exact) {
  Source source;
  const size_t vertexCount = exact.verticesWorld.size();
  source.positions.reserve(vertexCount * 3);
  for (const Vec3& p : exact.verticesWorld) {
    const Vec3 finite = IsFinite(p) ? p : Vec3{};
    source.positions.insert(
        source.positions.end(),
        {static_cast<float>(finite.x), static_cast<float>(finite.y), static_cast<float>(finite.z)});
  }
  std::vector<uint32_t> plain;
  plain.reserve(exact.triangles.size() * 3);
  for (const SceneTriangle& t : exact.triangles) {
    plain.insert(plain.end(), t.vertices.begin(), t.vertices.end());
  }
  source.indices.resize(plain.size());
  meshopt_generateShadowIndexBuffer(source.indices.data(), plain.data(), plain.size(),
                                    source.positions.data(), vertexCount, sizeof(float) * 3,
                                    sizeof(float) * 3);
  source.vertexFace.assign(vertexCount, kNone);
  for (size_t t = 0; t < exact.triangles.size(); ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      uint32_t& face = source.vertexFace[source.indices[3 * t + corner]];
      if (face == kNone) face = exact.TriangleFace(t);
    }
  }
  source.scaleModelUnits =
      meshopt_simplifyScale(source.positions.data(), vertexCount, sizeof(float) * 3);
  return source;
}

// The exact face a simplified triangle stands for: of the faces at its
// corners, the one whose normal is nearest its own; and that cosine.
std::pair<uint32_t, double> SourceFace(const Scene& exact, const Source& source,
                                       const uint32_t* corners, Vec3 normal) {
  uint32_t best = source.vertexFace[corners[0]];
  double bestDot = -std::numeric_limits<double>::infinity();
  for (int c = 0; c < 3; ++c) {
    const uint32_t face = source.vertexFace[corners[c]];
    const double dot = Dot(exact.facePlanesWorld[face].normal, normal);
    if (dot > bestDot) {
      bestDot = dot;
      best = face;
    }
  }
  return {best, bestDot};
}

// A level triangle's colour when textures are drawn: its source face's, or on
// a textured face the texture at the triangle's centroid, on the texture level
// its size in texels picks, times the face's colour (levels carry no images).
Rgb LevelColour(const Scene& exact, uint32_t sourceFace, Vec3 a, Vec3 b, Vec3 c) {
  const Rgb faceColour = exact.source.faceColors[sourceFace];
  const TextureLevels* texture = exact.textures.FaceTexture(sourceFace);
  if (texture == nullptr) return faceColour;
  const std::array<std::array<double, 2>, 3> uvs{FaceUvAt(exact, sourceFace, a),
                                                 FaceUvAt(exact, sourceFace, b),
                                                 FaceUvAt(exact, sourceFace, c)};
  double footprint = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double du = (uvs[(k + 1) % 3][0] - uvs[k][0]) * texture->WidthTexels();
    const double dv = (uvs[(k + 1) % 3][1] - uvs[k][1]) * texture->HeightTexels();
    footprint = std::max(footprint, std::sqrt(du * du + dv * dv));
  }
  const Rgb texel =
      texture->Sample((uvs[0][0] + uvs[1][0] + uvs[2][0]) / 3.0,
                      (uvs[0][1] + uvs[1][1] + uvs[2][1]) / 3.0, texture->LevelFor(footprint));
  return Rgb{texel.r * faceColour.r, texel.g * faceColour.g, texel.b * faceColour.b};
}

// A scene of the simplified triangles (indices into the exact vertices): the
// vertices they use, one face per triangle, the exact scene's frame and fit.
DetailLevel MakeLevel(const Scene& exact, const Source& source, std::span<const uint32_t> indices,
                      double errorModelUnits, std::vector<uint32_t>& newIndex) {
  DetailLevel level;
  Scene& scene = level.scene;
  scene.name = exact.name;
  scene.worldFromFile = exact.worldFromFile;
  scene.upAxis = exact.upAxis;
  scene.upAxisOverridden = exact.upAxisOverridden;
  scene.diagonalModelUnits = exact.diagonalModelUnits;
  scene.radiusModelUnits = exact.radiusModelUnits;
  scene.horizontalRadiusModelUnits = exact.horizontalRadiusModelUnits;
  scene.source.name = exact.source.name;
  scene.source.upAxisFile = exact.source.upAxisFile;
  scene.source.shiftZUp = exact.source.shiftZUp;
  std::vector<Vec3> verticesFile;
  level.errorModelUnits = errorModelUnits;

  // Step 1: the vertices used, in first-use order.
  std::vector<uint32_t> used;
  for (const uint32_t v : indices) {
    if (newIndex[v] != kNone) continue;
    newIndex[v] = static_cast<uint32_t>(used.size());
    used.push_back(v);
    scene.verticesWorld.push_back(exact.verticesWorld[v]);
    verticesFile.push_back(exact.VertexFile(v));
  }

  // Step 2: each triangle a face (the implicit maps), with its plane and its source face.
  const size_t triangleCount = indices.size() / 3;
  scene.triangles.reserve(triangleCount);
  scene.facePlanesWorld.reserve(triangleCount);
  FaceList& faces = scene.source.faces;  // kept: the triangles run {0, 1, 2}
  faces.corners.reserve(indices.size());
  level.sourceFaces.reserve(triangleCount);
  const bool coloured = !exact.source.faceColors.empty();
  const bool textured = coloured && exact.textures.Any();
  for (size_t t = 0; t < triangleCount; ++t) {
    const uint32_t* corners = &indices[3 * t];
    std::array<uint32_t, 3> local{newIndex[corners[0]], newIndex[corners[1]], newIndex[corners[2]]};
    const Vec3 a = scene.verticesWorld[local[0]], b = scene.verticesWorld[local[1]],
               c = scene.verticesWorld[local[2]];
    // Collapses along a row of the source's vertices can leave a fin: a sliver
    // with its corners on that row, across the surface. It shows no area,
    // only a wrong normal: left out.
    const Vec3 cross = Cross(b - a, c - a);
    const double longest = std::max({Dot(b - a, b - a), Dot(c - b, c - b), Dot(a - c, a - c)});
    Vec3 normal = Normalized(cross);
    auto [sourceFace, agreement] = SourceFace(exact, source, corners, normal);
    if (normal == Vec3{} ||
        (Length(cross) < kFinHeight * longest && std::abs(agreement) < kFinAgreement)) {
      continue;
    }
    // A collapse that folded a triangle over (rare) turns it inside out:
    // wound back as its source face, it covers its part of the fold from outside.
    if (agreement < 0.0) {
      std::swap(local[1], local[2]);
      normal = -normal;
      std::tie(sourceFace, agreement) = SourceFace(exact, source, corners, normal);
    }
    scene.facePlanesWorld.push_back({normal, Dot(normal, (a + b + c) * (1.0 / 3.0))});
    scene.triangles.push_back({local});
    faces.corners.insert(faces.corners.end(), local.begin(), local.end());
    level.sourceFaces.push_back(sourceFace);
    if (coloured) scene.source.faceColors.push_back(exact.source.faceColors[sourceFace]);
    if (textured) scene.textures.flatColours.push_back(LevelColour(exact, sourceFace, a, b, c));
  }
  faces.faceCount = scene.triangles.size();
  scene.source.KeepVerticesFile(scene.upAxis, scene.verticesWorld, verticesFile);
  scene.clusters = BuildClusters(scene);
  for (const uint32_t v : used) newIndex[v] = kNone;
  return level;
}

// Edge collapses of inputs this big run where a cancel can stop them at once
// (a child process): one meshopt_simplify call on them takes seconds.
constexpr size_t kChildFromTriangles = 500000;

// One level's edge collapse: the indices of `current` reduced towards
// targetTriangles within relativeError (meshopt_simplify); the reached error
// in stepError. Returns the index count, or nullopt when cancelled or when
// its child process died (then `failure` says so).
std::optional<size_t> Collapse(const Source& source, const std::vector<uint32_t>& current,
                               size_t targetTriangles, float relativeError,
                               std::vector<uint32_t>& simplified, float& stepError,
                               const std::atomic<bool>* cancel, std::string& failure) {
  const size_t vertexCount = source.positions.size() / 3;
  auto collapse = [&](uint32_t* destination, float* error) {
    // (meshopt_simplifySloppy is 3x faster here but twice the error, and stalls near 20k.)
    return meshopt_simplify(destination, current.data(), current.size(), source.positions.data(),
                            vertexCount, sizeof(float) * 3, targetTriangles * 3, relativeError, 0,
                            error);
  };
  if (cancel == nullptr || current.size() / 3 < kChildFromTriangles) {
    return collapse(simplified.data(), &stepError);
  }
  // The shared answer: the index count, the error, then the indices.
  struct Answer {
    size_t indexCount;
    float error;
  };
  constexpr size_t kIndicesAt = 16;
  static_assert(sizeof(Answer) <= kIndicesAt);
  size_t indexCount = 0;
  const ChildOutcome outcome = RunInChild(
      kIndicesAt + current.size() * sizeof(uint32_t),
      [&](std::byte* shared) {
        Answer answer{};
        answer.indexCount =
            collapse(reinterpret_cast<uint32_t*>(shared + kIndicesAt), &answer.error);
        std::memcpy(shared, &answer, sizeof answer);
      },
      [&](const std::byte* shared) {
        Answer answer{};
        std::memcpy(&answer, shared, sizeof answer);
        indexCount = std::min(answer.indexCount, current.size());
        stepError = answer.error;
        std::memcpy(simplified.data(), shared + kIndicesAt, indexCount * sizeof(uint32_t));
      },
      *cancel);
  switch (outcome) {
    case ChildOutcome::kAnswered:
      return indexCount;
    case ChildOutcome::kNoChild:  // here, to its end
      return collapse(simplified.data(), &stepError);
    case ChildOutcome::kDied:  // likely out of memory: not tried again here
      failure = "its edge collapse ended without an answer (out of memory?)";
      return std::nullopt;
    case ChildOutcome::kCancelled:
      return std::nullopt;
  }
  return std::nullopt;
}

// How many distinct vertices the (position-joined) indices use.
size_t JoinedVertexCount(const std::vector<uint32_t>& indices, size_t vertexCount) {
  std::vector<bool> used(vertexCount, false);
  size_t count = 0;
  for (const uint32_t v : indices) {
    if (used[v]) continue;
    used[v] = true;
    ++count;
  }
  return count;
}

}  // namespace

std::string_view DetailModeName(DetailMode mode) {
  return mode == DetailMode::kAuto ? "auto" : "off";
}

std::optional<DetailMode> ParseDetailMode(std::string_view name) {
  if (name == "auto") return DetailMode::kAuto;
  if (name == "off") return DetailMode::kOff;
  return std::nullopt;
}

DetailLevels BuildDetailLevels(const Scene& exact, const DetailBuildOptions& options) {
  DetailLevels result;
  result.exactTriangles = exact.triangles.size();
  if (exact.triangles.size() < options.minSourceTriangles) return result;
  // Polled between steps; a big edge collapse (the first level's is most of
  // the build) runs in a child process that a cancel stops at once.
  auto cancelled = [&] { return options.cancel != nullptr && options.cancel->load(); };
  Source source = MakeSource(exact);
  if (cancelled()) return result;
  const size_t vertexCount = exact.verticesWorld.size();
  std::vector<uint32_t> newIndex(vertexCount, kNone);
  // The joined indices are only the first level's input: moved, not copied
  // (a 10M-triangle scan's build peaks 114 MB lower).
  std::vector<uint32_t> current = std::move(source.indices);
  // Triangles repeated at the same positions (a triangle a million times
  // over, unwelded copies) make the edge collapse quadratic: the first of
  // each is kept (the triangles per joined vertex say when to look).
  if (current.size() / 3 >
      kRepeatCheckTrianglesPerVertex * JoinedVertexCount(current, vertexCount)) {
    DropRepeatedTriangles(current);
    if (cancelled()) return result;
    if (current.size() / 3 < options.minSourceTriangles) {
      result.skippedBecause = "its triangles repeat one another: fewer than " +
                              std::to_string(options.minSourceTriangles) + " differ";
      return result;
    }
  }
  std::vector<uint32_t> simplified(current.size());
  double relativeError = 0.0;  // accumulated over the levels: each is simplified from the last
  while (!cancelled()) {
    const size_t triangles = current.size() / 3;
    const auto target = static_cast<size_t>(static_cast<double>(triangles) / options.reduction);
    if (target < options.minTriangles) break;
    // Step 1: edge collapse within what error is left (stopped by a cancel).
    float stepError = 0.0F;
    const auto budget = static_cast<float>(options.maxRelativeError - relativeError);
    std::string failure;
    const std::optional<size_t> collapsed =
        Collapse(source, current, target, budget, simplified, stepError, options.cancel, failure);
    if (!collapsed) {
      if (result.levels.empty()) result.skippedBecause = failure;
      break;
    }
    const size_t indexCount = *collapsed;
    // Step 2: stop where the error budget (or the topology) stops the collapse.
    if (indexCount == 0 || indexCount > current.size() * 3 / 4 || cancelled()) break;
    relativeError += stepError;
    simplified.resize(indexCount);
    result.levels.push_back(
        MakeLevel(exact, source, simplified, relativeError * source.scaleModelUnits, newIndex));
    current.swap(simplified);
    simplified.resize(current.size());
  }
  if (cancelled()) result.levels.clear();
  return result;
}

DetailLevel BuildClusteredLevel(const Scene& exact, double cellModelUnits) {
  const double radius = exact.radiusModelUnits > 0.0 ? exact.radiusModelUnits : 1.0;
  const double wanted = cellModelUnits > 0.0 ? std::ceil(2.0 * radius / cellModelUnits) : 1.0;
  const auto across = static_cast<size_t>(std::clamp(wanted, 1.0, double{kMostClusterCellsAcross}));
  const double cellSize = 2.0 * radius / static_cast<double>(across);
  const auto cellOf = [&](double coordinate) {
    const double cell = std::floor((coordinate + radius) / cellSize);
    return static_cast<size_t>(std::clamp(cell, 0.0, static_cast<double>(across - 1)));
  };
  // Step 1: each vertex to its cell's first vertex.
  const size_t vertexCount = exact.verticesWorld.size();
  std::vector<uint32_t> firstInCell(across * across * across, kNone);
  std::vector<uint32_t> clusterOf(vertexCount, kNone);
  for (size_t v = 0; v < vertexCount; ++v) {
    const Vec3 p = exact.verticesWorld[v];
    if (!IsFinite(p)) continue;
    uint32_t& first = firstInCell[(cellOf(p.x) * across + cellOf(p.y)) * across + cellOf(p.z)];
    if (first == kNone) first = static_cast<uint32_t>(v);
    clusterOf[v] = first;
  }
  // Step 2: the triangles whose corners stay apart; each cluster's first face.
  Source source;
  source.vertexFace.assign(vertexCount, kNone);
  std::vector<uint32_t> indices;
  for (size_t t = 0; t < exact.triangles.size(); ++t) {
    const auto& corners = exact.triangles[t].vertices;
    const uint32_t a = clusterOf[corners[0]], b = clusterOf[corners[1]], c = clusterOf[corners[2]];
    if (a == kNone || b == kNone || c == kNone || a == b || b == c || a == c) continue;
    indices.insert(indices.end(), {a, b, c});
    for (const uint32_t v : {a, b, c}) {
      if (source.vertexFace[v] == kNone) source.vertexFace[v] = exact.TriangleFace(t);
    }
  }
  std::vector<uint32_t> newIndex(vertexCount, kNone);
  // A vertex moves at most a cell's diagonal.
  return MakeLevel(exact, source, indices, std::sqrt(3.0) * cellSize, newIndex);
}

size_t EstimateDetailBuildBytes(const Scene& exact, const DetailBuildOptions& options) {
  if (exact.triangles.size() < options.minSourceTriangles) return 0;
  // Spheres (half as many vertices as triangles) allocate 151 bytes a
  // triangle at their peak (termshade_alloc_tests) and hold 116-118 resident
  // (250k-2M triangles): 112 a triangle (indices, the first level) and 128 a
  // vertex (meshoptimizer's tables) leave room for its power-of-two tables.
  constexpr double kBytesPerTriangle = 112, kBytesPerVertex = 128;
  return static_cast<size_t>(kBytesPerTriangle * static_cast<double>(exact.triangles.size()) +
                             kBytesPerVertex * static_cast<double>(exact.verticesWorld.size()));
}

double TrianglesNeeded(const Scene& exact, const Camera& camera, const DetailTarget& target) {
  const double radius = exact.radiusModelUnits, rho = camera.view.rho;
  if (!(rho > 1.5 * radius) || !(radius > 0.0)) return std::numeric_limits<double>::infinity();
  // The bounding sphere's silhouette radius, in cell widths across and rows down.
  const double radiusCells = camera.projection.d * radius / std::sqrt(rho * rho - radius * radius);
  const double discSamples = std::numbers::pi * radiusCells * target.samplesAcross *
                             (radiusCells / camera.projection.cellAspect) * target.samplesDown;
  return 2.0 * discSamples / target.samplesPerTriangle;
}

size_t ChooseDetailLevel(const DetailLevels& levels, const Scene& exact, const Camera& camera,
                         const DetailTarget& target) {
  const double needed = TrianglesNeeded(exact, camera, target);
  const double rho = camera.view.rho, radius = exact.radiusModelUnits;
  // Samples per model unit at the model's nearest point.
  const double samplesPerUnit = camera.projection.d *
                                std::max(target.samplesAcross, target.samplesDown) /
                                std::max(rho - radius, 1e-300);
  size_t chosen = 0;
  for (size_t i = 0; i < levels.levels.size(); ++i) {
    const DetailLevel& level = levels.levels[i];
    if (static_cast<double>(level.scene.triangles.size()) < needed) break;
    if (level.errorModelUnits * samplesPerUnit > target.maxErrorSamples) break;
    chosen = i + 1;
  }
  return chosen;
}

const Scene& DetailScene(const DetailLevels& levels, const Scene& exact, size_t level) {
  return level == 0 || level > levels.levels.size() ? exact : levels.levels[level - 1].scene;
}

}  // namespace termshade
