#include "geometry/FaceList.h"

#include <algorithm>
#include <utility>

#include "process/HugePages.h"

namespace termshade {

FaceList TakeFaces(Mesh& mesh) {
  FaceList faces;
  faces.faceCount = mesh.FaceCount();
  bool allTriangles = true;
  for (size_t f = 0; f < faces.faceCount && allTriangles; ++f) {
    allTriangles = mesh.faceStarts[f + 1] - mesh.faceStarts[f] == 3;
  }
  const bool anyHidden =
      std::any_of(mesh.edgeHidden.begin(), mesh.edgeHidden.end(), [](uint8_t h) { return h != 0; });
  faces.corners = std::move(mesh.faceCorners);
  if (!allTriangles) faces.starts = std::move(mesh.faceStarts);
  if (anyHidden) faces.hidden = std::move(mesh.edgeHidden);
  // What was not taken is freed with its pages (HugePages.h).
  mesh.faceCorners.clear();
  FreeAndReleasePages(mesh.faceStarts);
  FreeAndReleasePages(mesh.edgeHidden);
  mesh.faceStarts.assign(1, 0);
  return faces;
}

}  // namespace termshade
