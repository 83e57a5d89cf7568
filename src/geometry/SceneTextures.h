#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/Mesh.h"
#include "geometry/TextureLevels.h"
#include "geometry/Vec3.h"

namespace termshade {

/// A face searched triangle by triangle for the one holding a point up to this many.
inline constexpr uint32_t kMostScannedTriangles = 16;

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
  /// Per scene triangle, its corners' coordinates (u0, v0, u1, v1, u2, v2),
  /// and for faces of more than kMostScannedTriangles triangles, the affine
  /// map from the face's plane to coordinates fitted to its corners
  /// (BuildFaceUvs): a lookup costs a few triangles at most.
  std::vector<std::array<float, 6>> triangleUvs;
  struct AffineUv {
    Vec3 uFromPoint, vFromPoint;  ///< u = uFromPoint . p + uOffset (world space)
    double uOffset = 0.0, vOffset = 0.0;
  };
  std::unordered_map<uint32_t, AffineUv> bigFaceUvs;
  /// A simplified level's faces (no images): each face's colour from its
  /// source face's texture, drawn in place of its face colour when textures are.
  std::vector<Rgb> flatColours;

  bool Any() const { return !faceTextures.empty(); }
  /// Textures change this scene's colours: images, or a level's flat colours.
  bool Colour() const { return Any() || !flatColours.empty(); }
  /// The face's texture when it has a decoded one, else nullptr.
  const TextureLevels* FaceTexture(size_t face) const {
    if (faceTextures.empty() || faceTextures[face] == kNoTexture) return nullptr;
    const TextureLevels& levels = images[faceTextures[face]];
    return levels.Empty() ? nullptr : &levels;
  }
  /// Bytes held: the images' levels and the faces' corners and coordinates.
  size_t HeldBytes() const;
};

/// Takes the mesh's textures (names, images, per-face indices and per-corner
/// coordinates; the corners are copied); empty when no face has a decoded image.
SceneTextures TakeSceneTextures(Mesh& mesh);
/// The bytes TakeSceneTextures keeps of a mesh (every image's levels: 4/3 of
/// its texels; the corners copied; their coordinates; a texture a face).
size_t SceneTextureBytes(const Mesh& mesh);
/// Gives them back to a mesh whose faces are `mesh`'s (SourceMesh).
void GiveBackTextures(const SceneTextures& textures, Mesh& mesh);

}  // namespace termshade
