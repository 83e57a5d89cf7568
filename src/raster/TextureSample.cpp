#include "raster/TextureSample.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/FaceUv.h"

namespace termshade {
namespace {

// A point on a face's plane, when the ray meets it.
struct FacePoint {
  bool hit = false;
  Vec3 pWorld;
};

// Where the ray through (x, y) of the view's frame meets the face's plane.
FacePoint MeetPlane(const FrameView& view, const FacePlane& plane, double x, double y) {
  const Projection& p = view.camera.projection;
  const Vec3 dirEye{(x - p.cx) / p.d, -(y - p.cy) * p.cellAspect / p.d, -1.0};
  // The eye's rotation is orthonormal: world = its transpose applied.
  const Mat4& m = view.eyeFromWorld;
  const Vec3 dirWorld{m.At(0, 0) * dirEye.x + m.At(1, 0) * dirEye.y + m.At(2, 0) * dirEye.z,
                      m.At(0, 1) * dirEye.x + m.At(1, 1) * dirEye.y + m.At(2, 1) * dirEye.z,
                      m.At(0, 2) * dirEye.x + m.At(1, 2) * dirEye.y + m.At(2, 2) * dirEye.z};
  const double along = Dot(plane.normal, dirWorld);
  if (std::fabs(along) < 1e-300) return {};
  const double t = (plane.offset - Dot(plane.normal, view.eyeWorld)) / along;
  if (!std::isfinite(t)) return {};
  return {true, view.eyeWorld + t * dirWorld};
}

}  // namespace

Rgb TexturedAlbedoAt(const Scene& scene, const FrameView& view, uint32_t face, double x, double y,
                     FrameStep step, int& level) {
  const TextureLevels& texture = *scene.textures.FaceTexture(face);
  const FacePlane& plane = scene.facePlanesWorld[face];
  // Step 1: the point and its neighbours' on the face's plane.
  const FacePoint here = MeetPlane(view, plane, x, y);
  if (!here.hit) return texture.Sample(0.0, 0.0, texture.LevelCount() - 1);
  const auto uv = FaceUvAt(scene, face, here.pWorld);
  // Step 2: the footprint, in full-size texels, picks the level (once a cell and face).
  double footprint = 0.0;
  for (const auto& [dx, dy] : {std::pair{step.across, 0.0}, std::pair{0.0, step.down}}) {
    if (level >= 0) break;
    const FacePoint next = MeetPlane(view, plane, x + dx, y + dy);
    if (!next.hit) continue;
    const auto uvNext = FaceUvAt(scene, face, next.pWorld);
    const double du = (uvNext[0] - uv[0]) * texture.WidthTexels();
    const double dv = (uvNext[1] - uv[1]) * texture.HeightTexels();
    footprint = std::max(footprint, std::sqrt(du * du + dv * dv));
  }
  if (level < 0) level = texture.LevelFor(footprint);
  Rgb texel = texture.Sample(uv[0], uv[1], level);
  // Step 3: times the face's colour (glTF's base colour factor).
  if (!scene.source.faceColors.empty()) {
    const Rgb factor = scene.source.faceColors[face];
    texel = Rgb{texel.r * factor.r, texel.g * factor.g, texel.b * factor.b};
  }
  return texel;
}

}  // namespace termshade
