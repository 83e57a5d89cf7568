#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geometry/FaceList.h"
#include "geometry/Rgb.h"
#include "geometry/UpAxis.h"
#include "geometry/Vec3.h"

namespace termshade {

/// What a prepared scene keeps of its model beyond the arrays the frame
/// reads, stored only where those arrays cannot give it back exactly.
struct SceneSource {
  std::string name;
  UpAxis upAxisFile = UpAxis::kPlusZ;
  std::vector<Rgb> faceColors;  ///< per face, or empty (Mesh::faceColors)
  std::vector<std::array<uint32_t, 2>> segments;
  /// The faces, closed parts outward; no corners when face f is exactly
  /// scene triangle f (Scene::Face gives them back from the triangles).
  FaceList faces;
  /// World vertices are ZUpFromFile(file) - shiftZUp; file vertices are
  /// FileFromZUp(world + shiftZUp) but for those listed here (or all of them
  /// in verticesFile, when many are not given back exactly).
  Vec3 shiftZUp;
  std::vector<Vec3> verticesFile;         ///< all of them, or empty
  std::vector<uint32_t> inexactVertices;  ///< ascending
  std::vector<Vec3> inexactVerticesFile;  ///< parallel to inexactVertices

  /// Keeps of verticesFile what verticesWorld does not give back bit for bit.
  void KeepVerticesFile(UpAxis upAxis, std::span<const Vec3> verticesWorld,
                        std::span<const Vec3> verticesFileIn);
  /// Vertex v in file space, exactly as the file gave it.
  Vec3 VertexFile(UpAxis upAxis, std::span<const Vec3> verticesWorld, size_t v) const;
};

}  // namespace termshade
