#include "geometry/Scene.h"

#include "geometry/FaceUv.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <utility>

#include "geometry/DuplicateTriangles.h"
#include "geometry/EdgeAdjacency.h"
#include "geometry/FaceList.h"
#include "geometry/FaceNormal.h"
#include "geometry/OutwardOrientation.h"
#include "geometry/Triangulate.h"
#include "process/HugePages.h"
#include "process/LoadThreads.h"

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

bool SameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

// ZUpFromFile(up, p) inline: the turn copies each component from one file
// component, its sign flipped or not (read off the turn's matrix).
class TurnUp {
 public:
  explicit TurnUp(UpAxis up) {
    const Mat4 turn = ZUpFromFile(up);
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) {
        if (turn.At(row, col) == 0.0) continue;
        source_[row] = col;
        negate_[row] = turn.At(row, col) < 0.0;
      }
    }
  }
  Vec3 operator()(Vec3 pFile) const {
    const double file[3] = {pFile.x, pFile.y, pFile.z};
    const auto component = [&](int row) {
      return negate_[row] ? -file[source_[row]] : file[source_[row]];
    };
    return {component(0), component(1), component(2)};
  }

 private:
  int source_[3] = {0, 1, 2};
  bool negate_[3] = {false, false, false};
};

// FileFromZUp(up, pWorld + center) has the bits of the file's vertex, whose
// turned copy is pZUp: the turn only moves and negates components (exact
// both ways), so each component of pWorld + center must be pZUp's.
bool GivesBackExactly(Vec3 pWorld, Vec3 center, Vec3 pZUp) {
  return SameBits(pWorld.x + center.x, pZUp.x) && SameBits(pWorld.y + center.y, pZUp.y) &&
         SameBits(pWorld.z + center.z, pZUp.z);
}

// Step 1 of PrepareScene, on the load threads: the file's vertices turned
// up (+z) and centered on their finite bounding box, in place (the array
// becomes scene.verticesWorld: no second array); of the file's vertices,
// only those world space does not give back bit for bit are kept
// (SceneSource::KeepVerticesFile's choice: listed, or all past an eighth).
void TakeVerticesAsWorld(Scene& scene, std::vector<Vec3> points) {
  const TurnUp turn(scene.upAxis);
  const size_t vertexCount = points.size();
  const int threads = LoadThreadCount(vertexCount);
  const auto parts = static_cast<size_t>(std::max(threads, 1));
  // Step 1a: the bounds of the finite turned points, a part a thread.
  std::vector<Bounds> partBounds(parts);
  RunRangesOnLoadThreads(threads, vertexCount, [&](int part, size_t begin, size_t end) {
    Bounds& bounds = partBounds[static_cast<size_t>(part)];
    for (size_t v = begin; v < end; ++v) {
      const Vec3 p = turn(points[v]);
      if (IsFinite(p)) bounds.Add(p);
    }
  });
  Bounds bounds;
  for (const Bounds& part : partBounds) {
    if (!part.Empty()) {
      bounds.Add(part.low);
      bounds.Add(part.high);
    }
  }
  const Vec3 center = bounds.Empty() ? Vec3{} : (bounds.low + bounds.high) * 0.5;
  scene.worldFromFile = Mat4::Translation(-center) * ZUpFromFile(scene.upAxis);
  scene.diagonalModelUnits = bounds.Empty() ? 0.0 : Length(bounds.high - bounds.low);
  scene.source.shiftZUp = center;

  // Step 1b: how many vertices world space does not give back, per part.
  std::vector<size_t> inexactBefore(parts + 1, 0);
  RunRangesOnLoadThreads(threads, vertexCount, [&](int part, size_t begin, size_t end) {
    size_t inexact = 0;
    for (size_t v = begin; v < end; ++v) {
      const Vec3 p = turn(points[v]);
      inexact += GivesBackExactly(p - center, center, p) ? 0 : 1;
    }
    inexactBefore[static_cast<size_t>(part) + 1] = inexact;
  });
  for (size_t part = 0; part < parts; ++part) inexactBefore[part + 1] += inexactBefore[part];
  SceneSource& source = scene.source;
  source.verticesFile.clear();
  const bool keepAll = inexactBefore.back() > vertexCount / 8;
  if (keepAll) source.verticesFile = points;
  source.inexactVertices.assign(keepAll ? 0 : inexactBefore.back(), 0);
  source.inexactVerticesFile.assign(source.inexactVertices.size(), Vec3{});

  // Step 1c: world space in place, the inexact file vertices listed
  // (ascending: each part writes its own stretch), the radius per part.
  std::vector<double> partRadius(parts, 0.0), partHorizontal(parts, 0.0);
  RunRangesOnLoadThreads(threads, vertexCount, [&](int part, size_t begin, size_t end) {
    size_t listed = inexactBefore[static_cast<size_t>(part)];
    double radius = 0.0, horizontal = 0.0;
    for (size_t v = begin; v < end; ++v) {
      const Vec3 pFile = points[v];
      const Vec3 p = turn(pFile);
      const bool finite = IsFinite(p);
      points[v] = p - center;
      if (finite) {
        radius = std::max(radius, Length(points[v]));
        horizontal = std::max(horizontal, std::hypot(points[v].x, points[v].y));
      }
      if (!keepAll && !GivesBackExactly(points[v], center, p)) {
        source.inexactVertices[listed] = static_cast<uint32_t>(v);
        source.inexactVerticesFile[listed++] = pFile;
      }
    }
    partRadius[static_cast<size_t>(part)] = radius;
    partHorizontal[static_cast<size_t>(part)] = horizontal;
  });
  for (size_t part = 0; part < parts; ++part) {
    scene.radiusModelUnits = std::max(scene.radiusModelUnits, partRadius[part]);
    scene.horizontalRadiusModelUnits =
        std::max(scene.horizontalRadiusModelUnits, partHorizontal[part]);
  }
  scene.verticesWorld = std::move(points);
}

// The face's plane through its mean corner (exact for planar faces, a
// least-squares-like compromise for slightly non-planar ones); zero when a
// corner is not finite.
template <typename Corners>
FacePlane PlaneOfFace(const std::vector<Vec3>& verticesWorld, const Corners& corners) {
  const auto pointAt = [&](size_t i) { return verticesWorld[corners[i]]; };
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

// The explicit face-to-triangle maps, written out once face f is no
// longer triangle f (faces before it each were their one triangle).
void MapFacesExplicitly(Scene& scene, size_t face, size_t faceCount) {
  scene.faceTriangleStarts.reserve(faceCount + 1);
  scene.triangleFaces.reserve(scene.triangles.capacity());
  for (uint32_t f = 0; f <= face; ++f) scene.faceTriangleStarts.push_back(f);
  for (uint32_t f = 0; f < face; ++f) scene.triangleFaces.push_back(f);
}

// The face's triangles, none when a corner is not finite; the maps between
// faces and triangles are kept only once they stop being the identity.
// A face with the corners of the one before it (hostile input: one polygon
// 200,000 times over) gets no triangles: the earlier face's cover it, and
// the z-buffer gives a tie to the lower face anyway.
void AddFaceTriangles(Scene& scene, const FaceList& faces, size_t face,
                      std::vector<Vec3>& cornersScratch,
                      std::vector<CornerTriangle>& trianglesScratch, int64_t& pointTests,
                      const std::atomic<bool>* cancel) {
  const auto corners = faces.Face(face);
  const auto before = face > 0 ? faces.Face(face - 1) : corners;
  if (face > 0 && std::equal(corners.begin(), corners.end(), before.begin(), before.end())) {
    if (scene.faceTriangleStarts.empty()) MapFacesExplicitly(scene, face, faces.FaceCount());
    scene.faceTriangleStarts.push_back(static_cast<uint32_t>(scene.triangles.size()));
    return;
  }
  trianglesScratch.clear();
  cornersScratch.clear();
  // Exactly what the face needs (no doubling's slack: one face may hold
  // millions of corners; LoadBudget.h counts kTriangulateBytesPerCorner).
  cornersScratch.reserve(corners.size());
  trianglesScratch.reserve(corners.size());
  bool finite = true;
  for (uint32_t v : corners) {
    cornersScratch.push_back(scene.verticesWorld[v]);
    finite = finite && IsFinite(scene.verticesWorld[v]);
  }
  if (finite) TriangulatePolygon(cornersScratch, trianglesScratch, &pointTests, cancel);
  const bool explicitMaps = !scene.faceTriangleStarts.empty();
  if (!explicitMaps && trianglesScratch.size() != 1) {
    MapFacesExplicitly(scene, face, faces.FaceCount());
  }
  for (const CornerTriangle& t : trianglesScratch) {
    scene.triangles.push_back({{corners[t[0]], corners[t[1]], corners[t[2]]}});
    if (!scene.triangleFaces.empty() || !scene.faceTriangleStarts.empty()) {
      scene.triangleFaces.push_back(static_cast<uint32_t>(face));
    }
  }
  if (!scene.faceTriangleStarts.empty()) {
    scene.faceTriangleStarts.push_back(static_cast<uint32_t>(scene.triangles.size()));
  }
}

// Step 4's common case, on the load threads: every face a triangle of three
// distinct finite corners, which TriangulatePolygon gives as its one
// triangle {2, 0, 1}. False (the triangles left half-written) as soon as a
// face is not, for the general path.
bool TriangulateTrianglesOnLoadThreads(Scene& scene, const FaceList& faces) {
  const size_t faceCount = faces.FaceCount();
  if (!faces.starts.empty() || faceCount == 0) return false;
  ResizeFaultedIn(scene.triangles, faceCount);
  std::atomic<bool> simple{true};
  const int threads = LoadThreadCount(faceCount);
  RunOnLoadThreads(threads, [&](int part) {
    const size_t begin = faceCount * static_cast<size_t>(part) / static_cast<size_t>(threads);
    const size_t end = faceCount * static_cast<size_t>(part + 1) / static_cast<size_t>(threads);
    const Vec3* points = scene.verticesWorld.data();
    for (size_t face = begin; face < end && simple.load(std::memory_order_relaxed); ++face) {
      const uint32_t* c = faces.corners.data() + 3 * face;
      const std::array<Vec3, 3> corners{points[c[0]], points[c[1]], points[c[2]]};
      if (!IsFinite(corners[0]) || !IsFinite(corners[1]) || !IsFinite(corners[2]) ||
          corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0] ||
          !IsFinite(NewellNormal(3, [&corners](size_t i) { return corners[i]; }))) {
        simple.store(false, std::memory_order_relaxed);
        return;
      }
      scene.triangles[face] = {{c[2], c[0], c[1]}};
    }
  });
  return simple.load();
}

// Face f of faces is scene triangle f, as Scene::Face gives it back, and no
// edge is hidden: the scene need not keep the faces.
bool FacesAreTheTriangles(const Scene& scene, const FaceList& faces) {
  if (!faces.starts.empty() || !faces.hidden.empty()) return false;
  if (scene.triangles.size() != faces.FaceCount()) return false;
  for (size_t f = 0; f < faces.FaceCount(); ++f) {
    const auto& t = scene.triangles[f].vertices;
    const uint32_t* c = faces.corners.data() + 3 * f;
    if (scene.TriangleFace(f) != f || t[1] != c[0] || t[2] != c[1] || t[0] != c[2]) {
      return false;
    }
  }
  return true;
}

// Step 1 of ConvexClosedSurface: every edge used once each way, and the
// faces connected through them.
bool OneClosedPart(const FaceList& faces, const EdgeAdjacency& adjacency) {
  const size_t faceCount = faces.FaceCount();
  std::vector<uint32_t> component(faceCount);
  for (uint32_t f = 0; f < faceCount; ++f) component[f] = f;
  auto root = [&](uint32_t f) {
    while (component[f] != f) f = component[f] = component[component[f]];
    return f;
  };
  bool closed = true;
  adjacency.ForEachEdge([&](uint32_t, std::span<const EdgeUse> uses) {
    if (!closed) return;
    if (uses.size() != 2 || uses[0].Forward() == uses[1].Forward()) {
      closed = false;  // open, non-manifold or inconsistently wound
      return;
    }
    component[root(uses[0].Face())] = root(uses[1].Face());
  });
  if (!closed) return false;
  for (uint32_t f = 0; f < faceCount; ++f) {
    if (root(f) != root(0)) return false;
  }
  return true;
}

// Whether the faces form a closed (every edge used once each way) connected
// surface, convex at every edge (each face's corners on or behind its
// neighbour's plane): a convex solid, where facing decides visibility. The
// planes are those Step 4 stores, computed here per edge so no face pairs
// need be kept, the edges split over the load threads.
// oneClosedPart: the answer to step 1 when already known.
bool ConvexClosedSurface(const std::vector<Vec3>& verticesWorld, const FaceList& faces,
                         const EdgeAdjacency& adjacency, double diagonalModelUnits,
                         std::optional<bool> oneClosedPart) {
  const size_t faceCount = faces.FaceCount();
  if (faceCount < 4) return false;
  if (!(oneClosedPart ? *oneClosedPart : OneClosedPart(faces, adjacency))) return false;
  const double tolerance = 1e-9 * std::max(1.0, diagonalModelUnits);
  auto behindPlane = [&](uint32_t f, uint32_t g) {
    const FacePlane plane = PlaneOfFace(verticesWorld, faces.Face(f));
    if (plane.normal == Vec3{}) return false;
    for (uint32_t v : faces.Face(g)) {
      if (Dot(plane.normal, verticesWorld[v]) - plane.offset > tolerance) return false;
    }
    return true;
  };
  // Step 2: convex at every edge, the edges split by smaller vertex.
  std::atomic<bool> convex{true};
  const uint64_t vertices = adjacency.VertexCount();
  const int threads = LoadThreadCount(adjacency.UseCount());
  RunOnLoadThreads(threads, [&](int part) {
    const auto begin = static_cast<uint32_t>(vertices * static_cast<uint64_t>(part) /
                                             static_cast<uint64_t>(threads));
    const auto end = static_cast<uint32_t>(vertices * static_cast<uint64_t>(part + 1) /
                                           static_cast<uint64_t>(threads));
    adjacency.ForEachEdgeFrom(begin, end, [&](uint32_t, std::span<const EdgeUse> uses) {
      if (!convex.load(std::memory_order_relaxed)) return;
      const uint32_t f = uses[0].Face(), g = uses[1].Face();
      if (!behindPlane(f, g) || !behindPlane(g, f)) convex.store(false, std::memory_order_relaxed);
    });
  });
  return convex.load();
}

}  // namespace

Mesh Scene::SourceMesh() const {
  Mesh mesh;
  mesh.name = source.name;
  mesh.upAxisFile = source.upAxisFile;
  mesh.faceColors = source.faceColors;
  mesh.segments = source.segments;
  mesh.verticesFile.reserve(verticesWorld.size());
  for (size_t v = 0; v < verticesWorld.size(); ++v) mesh.verticesFile.push_back(VertexFile(v));
  std::vector<uint32_t> corners;
  std::vector<uint8_t> hidden;
  for (size_t f = 0; f < FaceCount(); ++f) {
    const auto face = Face(f);
    corners.assign(face.begin(), face.end());
    hidden.clear();
    for (size_t i = 0; i < face.size(); ++i) hidden.push_back(EdgeHidden(f, i) ? 1 : 0);
    mesh.AddFace(corners, hidden);
  }
  GiveBackTextures(textures, mesh);
  return mesh;
}

namespace {

// PrepareScene's steps; nullopt as soon as a step sees `cancel` set.
std::optional<Scene> PrepareSceneSteps(Mesh mesh, std::optional<UpAxis> upOverride,
                                       const std::atomic<bool>* cancel) {
  // Polled between steps, every kFacesPerCancelPoll faces of the general
  // triangulation and every kEarsPerCancelPoll ears of a face.
  const auto cancelled = [cancel] {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
  };
  Scene scene;
  scene.name = mesh.name;
  scene.upAxis = upOverride.value_or(mesh.upAxisFile);
  scene.upAxisOverridden = upOverride.has_value();
  scene.source.name = std::move(mesh.name);
  scene.source.upAxisFile = mesh.upAxisFile;
  scene.source.faceColors = std::move(mesh.faceColors);
  scene.source.segments = std::move(mesh.segments);
  scene.textures = TakeSceneTextures(mesh);
  FaceList faces = TakeFaces(mesh);

  // Step 1: world space is file space turned up (+z), centered on the bounding
  // box, in the file's vertex array; of the file's vertices, only those world
  // space does not give back are kept.
  TakeVerticesAsWorld(scene, std::move(mesh.verticesFile));
  if (cancelled()) return std::nullopt;
  const size_t vertexCount = scene.verticesWorld.size();

  // Step 2: inside-out closed parts turned outward, once.
  auto adjacency = std::make_unique<EdgeAdjacency>(vertexCount, faces);
  bool oneClosedPart = false;
  scene.facesTurnedOutward =
      OrientClosedPartsOutward(faces, *adjacency, scene.verticesWorld, &oneClosedPart);
  std::optional<bool> knownClosed = oneClosedPart;
  if (scene.facesTurnedOutward > 0) {
    knownClosed.reset();  // reversed faces: edges to look at again
    adjacency.reset();
    adjacency = std::make_unique<EdgeAdjacency>(vertexCount, faces);
  }
  if (cancelled()) return std::nullopt;

  // Step 3: whether the model is a convex closed connected surface; the edge
  // uses are freed before the triangles and planes take their place.
  const bool convex = ConvexClosedSurface(scene.verticesWorld, faces, *adjacency,
                                          scene.diagonalModelUnits, knownClosed);
  adjacency->ReleasePages();
  adjacency.reset();
  if (cancelled()) return std::nullopt;

  // Step 4: per-face triangles (a face of n corners gives at most n - 2); the
  // faces are dropped when the triangles give them back.
  const size_t faceCount = faces.FaceCount();
  const size_t cornerCount = faces.corners.size();
  const bool simpleTriangles = TriangulateTrianglesOnLoadThreads(scene, faces);
  if (!simpleTriangles) {
    scene.triangles.clear();
    scene.triangles.reserve(cornerCount - std::min(cornerCount, 2 * faceCount));
    AdviseHugePages(scene.triangles);
    std::vector<Vec3> cornersScratch;
    std::vector<CornerTriangle> trianglesScratch;
    int64_t pointTests = ModelPointTestBudget(cornerCount);
    for (size_t face = 0; face < faceCount; ++face) {
      if (face % kFacesPerCancelPoll == 0 && cancelled()) return std::nullopt;
      AddFaceTriangles(scene, faces, face, cornersScratch, trianglesScratch, pointTests, cancel);
    }
  }
  if (cancelled()) return std::nullopt;
  // Triangles repeated over and over (hostile input: a triangle a million
  // times, a 1000-gon 20,000 times over the same corners) drawn once.
  const size_t repeated = DropRepeatedSceneTriangles(scene, faceCount);
  // (The fast path's triangles are the faces by construction.)
  if (repeated == 0 &&
      ((simpleTriangles && faces.hidden.empty()) || FacesAreTheTriangles(scene, faces))) {
    FreeAndReleasePages(faces.corners);  // a hole the planes do not fit in
    faces.Clear();
  } else {
    scene.source.faces = std::move(faces);
  }
  if (cancelled()) return std::nullopt;

  // Step 5: per-face planes, the faces split in ranges over the load threads;
  // where every face is its one triangle, its corners as a fixed-size array
  // (the same sums, unrolled).
  ResizeFaultedIn(scene.facePlanesWorld, faceCount);
  const bool facesAreTriangles = scene.source.faces.corners.empty();
  RunRangesOnLoadThreads(
      LoadThreadCount(faceCount), faceCount,
      [&scene, facesAreTriangles](int, size_t begin, size_t end) {
        for (size_t face = begin; face < end; ++face) {
          if (facesAreTriangles) {
            const auto& t = scene.triangles[face].vertices;  // Scene::Face's corners
            scene.facePlanesWorld[face] =
                PlaneOfFace(scene.verticesWorld, std::array<uint32_t, 3>{t[1], t[2], t[0]});
          } else {
            scene.facePlanesWorld[face] = PlaneOfFace(scene.verticesWorld, scene.Face(face));
          }
        }
      });
  if (cancelled()) return std::nullopt;
  BuildFaceUvs(scene);
  scene.clusters = BuildClusters(scene);
  if (cancelled()) return std::nullopt;
  scene.convexClosedSolid = convex && !scene.triangles.empty();
  return scene;
}

}  // namespace

Scene PrepareScene(Mesh mesh, std::optional<UpAxis> upOverride) {
  return *PrepareSceneSteps(std::move(mesh), upOverride, nullptr);
}

std::optional<Scene> PrepareScene(Mesh mesh, std::optional<UpAxis> upOverride,
                                  const std::atomic<bool>& cancel) {
  return PrepareSceneSteps(std::move(mesh), upOverride, &cancel);
}

}  // namespace termshade
