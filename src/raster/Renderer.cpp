#include "raster/Renderer.h"

#include <algorithm>
#include <cmath>

#include "geometry/ViewingTransform.h"
#include "raster/FixedPoint.h"
#include "raster/LineRasterizer.h"

namespace termshade {
namespace {

RasterVertex ToRaster(const CellPoint& p) {
  return {SnapToFixed(p.u), SnapToFixed(p.v), static_cast<float>(p.w)};
}

// The near plane sits a tiny, scale-relative distance in front of the eye.
double NearDistance(const Scene& scene) {
  return 1e-6 * (scene.diagonalModelUnits > 0.0 ? scene.diagonalModelUnits : 1.0);
}

}  // namespace

RenderStats Renderer::Render(const Scene& scene, const Camera& camera,
                             const RenderOptions& options, DepthBuffer& depth, CellBuffer& cells) {
  cells.Clear();
  depth.Clear();
  clipPlanes_ = MakeViewClipPlanes(camera.projection, NearDistance(scene));
  TransformVertices(scene, camera);
  ClassifyFaces(scene, camera, options);
  RenderStats stats;
  if (options.method == Method::kWire) {
    stats.trianglesDrawn = DrawEdges(scene, camera, options, depth, cells);
  } else {
    stats.trianglesDrawn = DrawSurfaces(scene, camera, options, depth, cells);
  }
  stats.facesVisible = ShadeCells(options, cells);
  return stats;
}

void Renderer::TransformVertices(const Scene& scene, const Camera& camera) {
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  const size_t count = scene.verticesWorld.size();
  verticesEye_.resize(count);
  rasterVertices_.resize(count);
  outCodes_.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const Vec3 pEye = TransformPoint(eyeFromWorld, scene.verticesWorld[i]);
    verticesEye_[i] = pEye;
    outCodes_[i] = static_cast<uint8_t>(OutCode(clipPlanes_, pEye));
    // Only vertices inside every plane are projected here; the others are clipped first.
    rasterVertices_[i] = outCodes_[i] == 0 ? ToRaster(ProjectToCell(camera.projection, pEye))
                                           : RasterVertex{};
  }
}

void Renderer::ClassifyFaces(const Scene& scene, const Camera& camera,
                             const RenderOptions& options) {
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  const Vec3 eyeWorld = EyePositionWorld(camera.view);
  const size_t faceCount = scene.FaceCount();
  faceDrawn_.resize(faceCount);
  faceSunDots_.resize(faceCount);
  for (size_t f = 0; f < faceCount; ++f) {
    const Vec3 nWorld = scene.faceNormalsWorld[f];
    // Front-facing: the eye is strictly in front of the face's plane (h < 0 in eye space).
    const bool front = Dot(nWorld, eyeWorld) > scene.facePlaneOffsets[f];
    faceDrawn_[f] = front || !options.cullBackFaces;
    const Vec3 nEye = TransformDirection(eyeFromWorld, front ? nWorld : -nWorld);
    faceSunDots_[f] = static_cast<float>(Dot(nEye, options.sunEye));
  }
}

int Renderer::DrawTriangle(const Scene& scene, const Camera& camera, uint32_t triangle,
                           DepthRule rule, DepthBuffer& depth, CellBuffer& cells) {
  const SceneTriangle& t = scene.triangles[triangle];
  const uint32_t faceNumber = t.face + 1;
  const unsigned codes[3] = {outCodes_[t.vertices[0]], outCodes_[t.vertices[1]],
                             outCodes_[t.vertices[2]]};
  // Fast path: wholly inside the near plane and the guard band.
  if ((codes[0] | codes[1] | codes[2]) == 0) {
    RasterizeTriangle(rasterVertices_[t.vertices[0]], rasterVertices_[t.vertices[1]],
                      rasterVertices_[t.vertices[2]], faceNumber, rule, depth, cells);
    return 1;
  }
  if ((codes[0] & codes[1] & codes[2]) != 0) return 0;
  const std::array<Vec3, 3> cornersEye{verticesEye_[t.vertices[0]], verticesEye_[t.vertices[1]],
                                       verticesEye_[t.vertices[2]]};
  if (!IsFinite(cornersEye[0]) || !IsFinite(cornersEye[1]) || !IsFinite(cornersEye[2])) return 0;
  ClippedPolygon clipped;
  ClipTriangle(cornersEye, clipPlanes_, clipped);
  if (clipped.count < 3) return 0;
  // The clipped polygon is convex: a fan from its first corner covers it.
  std::array<RasterVertex, 10> projected{};
  for (size_t i = 0; i < clipped.count; ++i) {
    projected[i] = ToRaster(ProjectToCell(camera.projection, clipped.corners[i]));
  }
  for (size_t i = 1; i + 1 < clipped.count; ++i) {
    RasterizeTriangle(projected[0], projected[i], projected[i + 1], faceNumber, rule, depth,
                      cells);
  }
  return 1;
}

int Renderer::DrawSurfaces(const Scene& scene, const Camera& camera,
                           const RenderOptions& options, DepthBuffer& depth, CellBuffer& cells) {
  int drawn = 0;
  const auto triangleCount = static_cast<uint32_t>(scene.triangles.size());
  if (options.method == Method::kPainter) {
    // Textbook painter: far to near by the sum of the vertices' eye z.
    painterOrder_.clear();
    for (uint32_t i = 0; i < triangleCount; ++i) {
      const SceneTriangle& t = scene.triangles[i];
      if (!faceDrawn_[t.face]) continue;
      const double zSum = verticesEye_[t.vertices[0]].z + verticesEye_[t.vertices[1]].z +
                          verticesEye_[t.vertices[2]].z;
      painterOrder_.emplace_back(zSum, i);
    }
    std::sort(painterOrder_.begin(), painterOrder_.end());
    for (const auto& [zSum, i] : painterOrder_) {
      drawn += DrawTriangle(scene, camera, i, DepthRule::kOverwrite, depth, cells);
    }
    return drawn;
  }
  const DepthRule rule =
      options.method == Method::kZBuffer ? DepthRule::kNearestWins : DepthRule::kOverwrite;
  for (uint32_t i = 0; i < triangleCount; ++i) {
    if (faceDrawn_[scene.triangles[i].face]) {
      drawn += DrawTriangle(scene, camera, i, rule, depth, cells);
    }
  }
  return drawn;
}

int Renderer::DrawEdges(const Scene& scene, const Camera& camera, const RenderOptions& options,
                        DepthBuffer& depth, CellBuffer& cells) {
  const auto topLevel = static_cast<int16_t>(options.ramp.LevelCount() - 1);
  int drawn = 0;
  for (const SceneEdge& edge : scene.edges) {
    Vec3 aEye = verticesEye_[edge.vertices[0]];
    Vec3 bEye = verticesEye_[edge.vertices[1]];
    if (!IsFinite(aEye) || !IsFinite(bEye) || !ClipSegment(aEye, bEye, clipPlanes_)) continue;
    const uint32_t faceNumber = edge.face == UINT32_MAX ? 0 : edge.face + 1;
    DrawLine(ProjectToCell(camera.projection, aEye), ProjectToCell(camera.projection, bEye),
             camera.projection.cellAspect, faceNumber, topLevel, depth, cells);
    ++drawn;
  }
  return drawn;
}

// Turns the face seen in each cell into a ramp glyph; returns the faces seen.
int Renderer::ShadeCells(const RenderOptions& options, CellBuffer& cells) {
  auto& faces = cells.FaceNumbers();
  faceSeen_.assign(faceSunDots_.size(), 0);
  for (uint32_t faceNumber : faces) {
    if (faceNumber != 0) faceSeen_[faceNumber - 1] = 1;
  }
  int seenCount = 0;
  double minDot = INFINITY, maxDot = -INFINITY;
  for (size_t f = 0; f < faceSeen_.size(); ++f) {
    if (!faceSeen_[f]) continue;
    ++seenCount;
    minDot = std::min(minDot, static_cast<double>(faceSunDots_[f]));
    maxDot = std::max(maxDot, static_cast<double>(faceSunDots_[f]));
  }
  if (options.method == Method::kWire) return seenCount;

  faceLevels_.resize(faceSunDots_.size());
  for (size_t f = 0; f < faceSeen_.size(); ++f) {
    if (!faceSeen_[f]) continue;
    const double dot = faceSunDots_[f];
    const double intensity = options.shade == ShadeMode::kContrast
                                 ? ContrastIntensity(dot, minDot, maxDot, options.ambient)
                                 : LambertIntensity(dot, options.ambient);
    faceLevels_[f] = static_cast<int16_t>(options.ramp.LevelFor(intensity));
  }
  auto& glyphs = cells.Glyphs();
  auto& levels = cells.Levels();
  for (size_t i = 0; i < faces.size(); ++i) {
    if (faces[i] == 0) continue;
    levels[i] = faceLevels_[faces[i] - 1];
    glyphs[i] = options.ramp.Glyph(levels[i]);
  }
  return seenCount;
}

}  // namespace termshade
