#include "geometry/Mesh.h"

namespace termshade {

void Mesh::AddFace(std::span<const uint32_t> corners, std::span<const uint8_t> hidden) {
  for (size_t i = 0; i < corners.size(); ++i) {
    faceCorners.push_back(corners[i]);
    edgeHidden.push_back(i < hidden.size() ? hidden[i] : 0);
  }
  faceStarts.push_back(static_cast<uint32_t>(faceCorners.size()));
}

}  // namespace termshade
