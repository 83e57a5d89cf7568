#include "geometry/SceneTextures.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace termshade {

size_t SceneTextures::HeldBytes() const {
  size_t bytes = faceTextures.size() * sizeof(uint32_t) + uvStarts.size() * sizeof(uint32_t) +
                 uvCorners.size() * sizeof(uint32_t) + cornerUvs.size() * sizeof(cornerUvs[0]) +
                 triangleUvs.size() * sizeof(triangleUvs[0]) +
                 bigFaceUvs.size() * (sizeof(AffineUv) + 32);
  for (const TextureLevels& levels : images) {
    for (int level = 0; level < levels.LevelCount(); ++level) bytes += levels.LevelBytes(level);
  }
  return bytes;
}

size_t SceneTextureBytes(const Mesh& mesh) {
  if (mesh.faceTextures.empty()) return 0;
  // (A triangle's coordinates: at most as many triangles as corners.)
  size_t bytes = mesh.faceCorners.size() * (sizeof(uint32_t) + sizeof(mesh.cornerUvs[0]) + 24) +
                 mesh.faceStarts.size() * sizeof(uint32_t) +
                 mesh.faceTextures.size() * sizeof(uint32_t);
  for (const TextureImage& image : mesh.textureImages) bytes += image.srgbTexels.size() * 4 / 3;
  return bytes;
}

SceneTextures TakeSceneTextures(Mesh& mesh) {
  SceneTextures out;
  const bool usable = !mesh.faceTextures.empty() && mesh.faceTextures.size() == mesh.FaceCount() &&
                      mesh.cornerUvs.size() == mesh.faceCorners.size() &&
                      mesh.textureImages.size() == mesh.textures.size() &&
                      std::any_of(mesh.textureImages.begin(), mesh.textureImages.end(),
                                  [](const TextureImage& image) { return image.Decoded(); });
  if (!usable) return out;
  out.names = std::move(mesh.textures);
  out.images.reserve(mesh.textureImages.size());
  for (TextureImage& image : mesh.textureImages) out.images.emplace_back(std::move(image));
  mesh.textureImages.clear();
  out.faceTextures = std::move(mesh.faceTextures);
  for (uint32_t& texture : out.faceTextures) {
    if (texture != kNoTexture && texture >= out.images.size()) texture = kNoTexture;
  }
  out.uvStarts = mesh.faceStarts;
  out.uvCorners = mesh.faceCorners;
  out.cornerUvs = std::move(mesh.cornerUvs);
  return out;
}

void GiveBackTextures(const SceneTextures& textures, Mesh& mesh) {
  if (!textures.Any()) return;
  mesh.textures = textures.names;
  for (const TextureLevels& levels : textures.images) {
    mesh.textureImages.push_back(levels.Empty() ? TextureImage{} : levels.Image());
  }
  mesh.faceTextures = textures.faceTextures;
  // Each face's corners by vertex, for a binary search per corner (n log n a face).
  mesh.cornerUvs.clear();
  std::vector<std::pair<uint32_t, std::array<float, 2>>> sorted;
  for (size_t face = 0; face < mesh.FaceCount(); ++face) {
    sorted.clear();
    for (uint32_t at = textures.uvStarts[face]; at < textures.uvStarts[face + 1]; ++at) {
      sorted.emplace_back(textures.uvCorners[at], textures.cornerUvs[at]);
    }
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const uint32_t vertex : mesh.Face(face)) {
      const auto at = std::lower_bound(sorted.begin(), sorted.end(), vertex,
                                       [](const auto& a, uint32_t v) { return a.first < v; });
      mesh.cornerUvs.push_back(at != sorted.end() && at->first == vertex ? at->second
                                                                         : std::array<float, 2>{});
    }
  }
}

}  // namespace termshade
