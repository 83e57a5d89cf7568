#pragma once

#include <cstddef>

#include "geometry/Mesh.h"
#include "geometry/Vec3.h"

namespace termshade {

/// What a mesh is made of, as `termshade info` reports it (file coordinates).
struct MeshReport {
  size_t vertices = 0;          ///< in the file (after dropping unused ones, where a reader does)
  size_t faces = 0;             ///< polygons as the file gives them
  size_t segments = 0;          ///< two-vertex lines (drawn in wire mode only)
  size_t parts = 0;             ///< groups of faces connected through shared vertices
  size_t openEdges = 0;         ///< edges of exactly one face: 0 for closed surfaces
  size_t nonManifoldEdges = 0;  ///< edges of three faces or more
  size_t faceColours = 0;       ///< distinct face colours the file gives; 0: none given
  Vec3 boundsMin;               ///< bounding box of the vertices faces use
  Vec3 boundsMax;
};

/// Counts a mesh's parts and edges and measures its bounds: O(corners log corners).
MeshReport ReportMesh(const Mesh& mesh);

}  // namespace termshade
