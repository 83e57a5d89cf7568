#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/Mat4.h"
#include "geometry/Mesh.h"

namespace termshade {

/// One triangle of a triangulated face: vertex indices and the 0-based face.
struct SceneTriangle {
  std::array<uint32_t, 3> vertices{};
  uint32_t face = 0;
};

/// A drawable line for wire-frame mode; face is the first face that has it
/// (or UINT32_MAX for a free segment).
struct SceneEdge {
  std::array<uint32_t, 2> vertices{};
  uint32_t face = 0;
};

/// A model made ready for rendering from any view: centered on its bounding
/// box (world space), faces triangulated once, unit normals and planes known.
struct Scene {
  std::string name;
  Mat4 worldFromFile;
  std::vector<Vec3> verticesWorld;
  std::vector<SceneTriangle> triangles;
  std::vector<Vec3> faceNormalsWorld;     ///< unit Newell normals (zero when degenerate)
  std::vector<double> facePlaneOffsets;   ///< h with n . p = h for the face's mean corner, world
  std::vector<uint32_t> faceTriangleStarts;  ///< FaceCount() + 1 entries into triangles
  std::vector<SceneEdge> edges;
  Mesh mesh;                    ///< the source model, for exact references and export
  double diagonalModelUnits = 0.0;  ///< bounding-box diagonal
  double radiusModelUnits = 0.0;    ///< of the smallest sphere about the origin holding every vertex

  size_t FaceCount() const { return faceNormalsWorld.size(); }
};

/// Centers, triangulates and measures a mesh. Faces with non-finite
/// coordinates keep their number but get no triangles.
Scene PrepareScene(Mesh mesh);

}  // namespace termshade
