#include "geometry/SceneTextures.h"

#include <algorithm>

namespace termshade {

std::array<float, 2> SceneTextures::UvAt(size_t face, uint32_t vertex) const {
  for (uint32_t at = uvStarts[face]; at < uvStarts[face + 1]; ++at) {
    if (uvCorners[at] == vertex) return cornerUvs[at];
  }
  return {0.0F, 0.0F};
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
  for (const TextureImage& image : mesh.textureImages) out.images.emplace_back(image);
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
  mesh.cornerUvs.clear();
  for (size_t face = 0; face < mesh.FaceCount(); ++face) {
    for (const uint32_t vertex : mesh.Face(face))
      mesh.cornerUvs.push_back(textures.UvAt(face, vertex));
  }
}

}  // namespace termshade
