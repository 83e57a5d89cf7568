#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/Mesh.h"
#include "geometry/TextureLevels.h"

namespace termshade {

/// What a prepared scene keeps to texture its faces: each face's texture and
/// its corners' coordinates, looked up by vertex (the faces' corners may be
/// reversed or triangulated; a corner keeps its coordinates), and each
/// texture's levels. Empty when no face has a decoded texture.
struct SceneTextures {
  std::vector<std::string> names;      ///< Mesh::textures
  std::vector<TextureLevels> images;   ///< parallel to names; empty where not decoded
  std::vector<uint32_t> faceTextures;  ///< per face: index into images, or kNoTexture
  /// The faces' corners as the file gave them (faceCount + 1 starts), and their coordinates.
  std::vector<uint32_t> uvStarts;
  std::vector<uint32_t> uvCorners;
  std::vector<std::array<float, 2>> cornerUvs;

  bool Any() const { return !faceTextures.empty(); }
  /// The face's texture when it has a decoded one, else nullptr.
  const TextureLevels* FaceTexture(size_t face) const {
    if (faceTextures.empty() || faceTextures[face] == kNoTexture) return nullptr;
    const TextureLevels& levels = images[faceTextures[face]];
    return levels.Empty() ? nullptr : &levels;
  }
  /// The texture coordinates of vertex `vertex` as a corner of `face` (its first such corner).
  std::array<float, 2> UvAt(size_t face, uint32_t vertex) const;
};

/// Takes the mesh's textures (names, images, per-face indices and per-corner
/// coordinates; the corners are copied); empty when no face has a decoded image.
SceneTextures TakeSceneTextures(Mesh& mesh);
/// Gives them back to a mesh whose faces are `mesh`'s (SourceMesh).
void GiveBackTextures(const SceneTextures& textures, Mesh& mesh);

}  // namespace termshade
