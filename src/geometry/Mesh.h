#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geometry/Rgb.h"
#include "geometry/TextureImage.h"
#include "geometry/UpAxis.h"
#include "geometry/Vec3.h"

namespace termshade {

/// Most textures a mesh names, and most bytes in one's name (the import's answer is refused past
/// them).
inline constexpr size_t kMaxTextures = 4096;
inline constexpr size_t kMaxTextureNameBytes = 4096;
/// Mesh::faceTextures of a face without a texture.
inline constexpr uint32_t kNoTexture = UINT32_MAX;

/// A polygon model as read from a file: vertices in file space, faces as
/// counter-clockwise (seen from outside) lists of 0-based vertex indices.
struct Mesh {
  std::string name;
  std::vector<Vec3> verticesFile;
  /// Corners of all faces, face after face; faceStarts has FaceCount() + 1 entries.
  std::vector<uint32_t> faceCorners;
  std::vector<uint32_t> faceStarts{0};
  /// Parallel to faceCorners: the edge from this corner to the next is not drawn as a line.
  std::vector<uint8_t> edgeHidden;
  /// Two-vertex entries of the file: line segments (drawn in wire mode only).
  std::vector<std::array<uint32_t, 2>> segments;
  /// Per face, the colour the file gives (material diffuse, or vertex colours
  /// averaged over the face); empty when the file gives none (SPEC 10).
  std::vector<Rgb> faceColors;
  /// The base-colour textures the file's materials name, each once, as the
  /// file writes them (a path relative to the model's folder, or "*N" for
  /// the file's Nth embedded image).
  std::vector<std::string> textures;
  /// Parallel to textures: the decoded images (or why one is not), when the
  /// loader decodes them; empty otherwise.
  std::vector<TextureImage> textureImages;
  /// Per face: its index into textures, or kNoTexture; empty when no face has one.
  std::vector<uint32_t> faceTextures;
  /// Parallel to faceCorners: each corner's texture coordinates (u right, v
  /// up, 0..1 across the image, repeating); empty when faceTextures is.
  std::vector<std::array<float, 2>> cornerUvs;
  /// The file's up axis: what the file declares, else its format's convention (SPEC 10).
  UpAxis upAxisFile = UpAxis::kPlusZ;
  /// Who read the file and as what ("termshade OBJ reader", "Assimp (import
  /// helper), as dae"); set by LoadModelFile, for reports.
  std::string reader;

  size_t FaceCount() const { return faceStarts.size() - 1; }
  std::span<const uint32_t> Face(size_t face) const {
    return {faceCorners.data() + faceStarts[face], faceStarts[face + 1] - faceStarts[face]};
  }
  /// The edge from corner i of the face to the next is not drawn as a line.
  bool EdgeHidden(size_t face, size_t i) const { return edgeHidden[faceStarts[face] + i] != 0; }
  void AddFace(std::span<const uint32_t> corners, std::span<const uint8_t> hidden = {});
};

}  // namespace termshade
