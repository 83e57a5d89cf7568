#include "raster/ClipToRaster.h"

#include "raster/FixedPoint.h"

namespace termshade {

static_assert(std::tuple_size_v<decltype(ClippedPolygon::corners)> == kClippedCornersMax);

size_t ClipToRaster(const Scene& scene, uint32_t triangle, const Mat4& eyeFromWorld,
                    const ViewClipPlanes& clipPlanes, const Projection& projection,
                    std::array<RasterVertex, kClippedCornersMax>& projected) {
  const SceneTriangle& t = scene.triangles[triangle];
  const std::array<Vec3, 3> cornersEye{
      TransformPoint(eyeFromWorld, scene.verticesWorld[t.vertices[0]]),
      TransformPoint(eyeFromWorld, scene.verticesWorld[t.vertices[1]]),
      TransformPoint(eyeFromWorld, scene.verticesWorld[t.vertices[2]])};
  if (!IsFinite(cornersEye[0]) || !IsFinite(cornersEye[1]) || !IsFinite(cornersEye[2])) return 0;
  ClippedPolygon clipped;
  ClipTriangle(cornersEye, clipPlanes, clipped);
  if (clipped.count < 3) return 0;
  for (size_t i = 0; i < clipped.count; ++i) {
    const CellPoint p = ProjectToCell(projection, clipped.corners[i]);
    projected[i] = {SnapToFixed(p.u), SnapToFixed(p.v), static_cast<float>(p.w)};
  }
  return clipped.count;
}

}  // namespace termshade
