#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/Clusters.h"
#include "geometry/Mat4.h"
#include "geometry/Mesh.h"
#include "geometry/SceneEdges.h"
#include "geometry/SceneHierarchy.h"
#include "geometry/SceneSource.h"
#include "geometry/SceneTextures.h"
#include "geometry/UpAxis.h"

namespace termshade {

/// One triangle of a triangulated face: vertex indices (its face is
/// Scene::TriangleFace).
struct SceneTriangle {
  std::array<uint32_t, 3> vertices{};
};

/// A face's plane n . p = offset: the unit Newell normal (zero when the face
/// is degenerate) through the mean of its corners.
struct FacePlane {
  Vec3 normal;
  double offset = 0.0;
  /// Front-facing as seen from pWorld: strictly in front of the plane (h < 0 in eye space).
  bool FacesPoint(Vec3 pWorld) const { return Dot(normal, pWorld) > offset; }
};

/// A model made ready for rendering from any view: turned so its up axis is
/// +z and centered on its bounding box (world space, SPEC 1), closed parts
/// turned outward, faces triangulated once, unit normals and planes known.
struct Scene {
  std::string name;
  Mat4 worldFromFile;              ///< the up-axis turn, then the shift to the center
  UpAxis upAxis = UpAxis::kPlusZ;  ///< the file axis turned to +z
  bool upAxisOverridden = false;   ///< upAxis was asked for, not the file's own
  size_t facesTurnedOutward = 0;   ///< faces of inside-out closed parts reversed
  std::vector<Vec3> verticesWorld;
  std::vector<SceneTriangle> triangles;
  std::vector<FacePlane> facePlanesWorld;  ///< per face, world space
  /// Where each face's triangles start: FaceCount() + 1 entries into
  /// triangles; empty when every face is one triangle, face f triangle f.
  std::vector<uint32_t> faceTriangleStarts;
  /// Per triangle, its 0-based face; empty when triangle t is face t.
  std::vector<uint32_t> triangleFaces;
  SceneClusters clusters;  ///< the triangles in runs, for culling whole runs per frame
  /// The triangles' hierarchy for RayCastStage, once a front end has
  /// built and attached it (big scenes drawn many times).
  SceneHierarchy hierarchy;
  SceneTextures textures;  ///< the faces' base-colour textures, when the file gives decoded ones
  SceneSource source;  ///< the rest of the model (closed parts outward), where the arrays lack it
  double diagonalModelUnits = 0.0;  ///< bounding-box diagonal
  double radiusModelUnits = 0.0;  ///< of the smallest sphere about the origin holding every vertex
  /// Of the smallest cylinder about the up (z) axis holding every vertex:
  /// what orbiting can bring to the left or right of the view.
  double horizontalRadiusModelUnits = 0.0;
  /// One closed, consistently oriented, connected surface with every edge
  /// convex: back-face culling alone draws it exactly (the `auto` method).
  bool convexClosedSolid = false;

  size_t FaceCount() const { return facePlanesWorld.size(); }
  /// The face of triangle t.
  uint32_t TriangleFace(size_t t) const {
    return triangleFaces.empty() ? static_cast<uint32_t>(t) : triangleFaces[t];
  }
  /// The face's triangles are [FaceTrianglesBegin(f), FaceTrianglesBegin(f + 1)).
  uint32_t FaceTrianglesBegin(size_t face) const {
    return faceTriangleStarts.empty() ? static_cast<uint32_t>(face) : faceTriangleStarts[face];
  }
  /// A face's corners (vertex indices), counter-clockwise seen from outside.
  FaceCorners Face(size_t face) const {
    if (!source.faces.corners.empty()) return source.faces.Face(face);
    const auto& t = triangles[face].vertices;  // TriangulatePolygon's {2, 0, 1} of the corners
    return FaceCorners(std::array<uint32_t, 3>{t[1], t[2], t[0]});
  }
  bool EdgeHidden(size_t face, size_t i) const { return source.faces.EdgeHidden(face, i); }
  /// Vertex v as the file gives it.
  Vec3 VertexFile(size_t v) const { return source.VertexFile(upAxis, verticesWorld, v); }
  /// The model as read (closed parts outward), rebuilt: to prepare it again.
  Mesh SourceMesh() const;
  /// The lines wire mode draws (SceneEdges.h), built on first use.
  const std::vector<SceneEdge>& Edges() const { return edges_.Get(*this); }

 private:
  LazySceneEdges edges_;
};

/// Turns, centers, orients, triangulates and measures a mesh. The up axis is
/// upOverride when given, else mesh.upAxisFile. Faces with non-finite
/// coordinates keep their number but get no triangles.
Scene PrepareScene(Mesh mesh, std::optional<UpAxis> upOverride = std::nullopt);
/// The same, stopped early (nullopt, nothing kept) once `cancel` is set: it
/// is polled between the steps, every kFacesPerCancelPoll faces and every
/// kEarsPerCancelPoll ears of one face.
std::optional<Scene> PrepareScene(Mesh mesh, std::optional<UpAxis> upOverride,
                                  const std::atomic<bool>& cancel);
/// Faces triangulated one by one between two looks at a cancel flag.
inline constexpr size_t kFacesPerCancelPoll = 4096;

}  // namespace termshade
