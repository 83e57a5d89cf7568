#include "raster/WireStage.h"

#include "geometry/ViewingTransform.h"
#include "raster/LineRasterizer.h"

namespace termshade {

int DrawWireFrame(const Scene& scene, const FrameView& view, int16_t level, DepthBuffer& depth,
                  CellBuffer& cells) {
  const Projection& projection = view.camera.projection;
  int drawn = 0;
  for (const SceneEdge& edge : scene.Edges()) {
    Vec3 aEye = TransformPoint(view.eyeFromWorld, scene.verticesWorld[edge.vertices[0]]);
    Vec3 bEye = TransformPoint(view.eyeFromWorld, scene.verticesWorld[edge.vertices[1]]);
    if (!IsFinite(aEye) || !IsFinite(bEye) || !ClipSegment(aEye, bEye, view.clipPlanes)) continue;
    const uint32_t faceNumber = edge.face == UINT32_MAX ? 0 : edge.face + 1;
    DrawLine(ProjectToCell(projection, aEye), ProjectToCell(projection, bEye),
             projection.cellAspect, faceNumber, level, depth, cells);
    ++drawn;
  }
  return drawn;
}

}  // namespace termshade
