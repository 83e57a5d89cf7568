#include "raster/Renderer.h"

#include <algorithm>
#include <cmath>

#include "geometry/FixedRange.h"
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
  stats.facesVisible = ShadeCells(scene, options, cells);
  return stats;
}

void Renderer::TransformVertices(const Scene& scene, const Camera& camera) {
  eyeFromWorld_ = EyeFromWorld(camera.view);
  const Mat4& eyeFromWorld = eyeFromWorld_;
  const Projection& proj = camera.projection;
  const size_t count = scene.verticesWorld.size();
  zEye_.resize(count);
  rasterVertices_.resize(count);
  outCodes_.resize(count);
  const double vScale = proj.d / proj.cellAspect;
  // A vertex this far inside every clip plane is inside for certain, whatever
  // the rounding; only the others need the exact out-codes.
  const double nearZ = 2.0 * -clipPlanes_[0].offset;
  const double xLimit = 0.5 * (kClipRangeCells - proj.cx), yLimit = 0.5 * (kClipRangeCells - proj.cy);
  for (size_t i = 0; i < count; ++i) {
    const Vec3 pEye = TransformPoint(eyeFromWorld, scene.verticesWorld[i]);
    zEye_[i] = pEye.z;
    // ProjectToCell, inlined: u = cx + d x w, v = cy - d y w / a with w = -1/z.
    const double w = -1.0 / pEye.z;
    const double xCells = proj.d * pEye.x * w, yCells = vScale * pEye.y * w;
    if (pEye.z <= -nearZ && std::fabs(xCells) <= xLimit && std::fabs(yCells) <= yLimit) {
      outCodes_[i] = 0;
      rasterVertices_[i] = {SnapToFixed(proj.cx + xCells), SnapToFixed(proj.cy - yCells),
                            static_cast<float>(w)};
      continue;
    }
    const unsigned code = OutCode(clipPlanes_, pEye);
    outCodes_[i] = static_cast<uint8_t>(code);
    rasterVertices_[i] = code == 0 ? ToRaster(ProjectToCell(proj, pEye)) : RasterVertex{};
  }
}

void Renderer::ClassifyFaces(const Scene& scene, const Camera& camera,
                             const RenderOptions& options) {
  const Vec3 eyeWorld = EyePositionWorld(camera.view);
  const size_t faceCount = scene.FaceCount();
  faceFront_.resize(faceCount);
  faceDrawn_.resize(faceCount);
  for (size_t f = 0; f < faceCount; ++f) {
    // Front-facing: the eye is strictly in front of the face's plane (h < 0 in eye space).
    const bool front = Dot(scene.faceNormalsWorld[f], eyeWorld) > scene.facePlaneOffsets[f];
    faceFront_[f] = front;
    faceDrawn_[f] = front || !options.cullBackFaces;
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
    const RasterVertex& a = rasterVertices_[t.vertices[0]];
    const RasterVertex& b = rasterVertices_[t.vertices[1]];
    const RasterVertex& c = rasterVertices_[t.vertices[2]];
    if (MayCoverSample(a, b, c, cells.WidthCells(), cells.HeightCells())) {
      RasterizeTriangle(a, b, c, faceNumber, rule, depth, cells);
    }
    return 1;
  }
  if ((codes[0] & codes[1] & codes[2]) != 0) return 0;
  // Rare: recompute eye coordinates rather than store them for every vertex.
  const std::array<Vec3, 3> cornersEye{TransformPoint(eyeFromWorld_, scene.verticesWorld[t.vertices[0]]),
                                       TransformPoint(eyeFromWorld_, scene.verticesWorld[t.vertices[1]]),
                                       TransformPoint(eyeFromWorld_, scene.verticesWorld[t.vertices[2]])};
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
  if (options.method == Method::kPainter) {
    const auto triangleCount = static_cast<uint32_t>(scene.triangles.size());
    // Textbook painter: far to near by the sum of the vertices' eye z.
    painterOrder_.clear();
    for (uint32_t i = 0; i < triangleCount; ++i) {
      const SceneTriangle& t = scene.triangles[i];
      if (!faceDrawn_[t.face]) continue;
      const double zSum = zEye_[t.vertices[0]] + zEye_[t.vertices[1]] + zEye_[t.vertices[2]];
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
  // Face by face, so culled faces' triangles are never even loaded.
  for (size_t f = 0; f < scene.FaceCount(); ++f) {
    if (!faceDrawn_[f]) continue;
    for (uint32_t i = scene.faceTriangleStarts[f]; i < scene.faceTriangleStarts[f + 1]; ++i) {
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
    Vec3 aEye = TransformPoint(eyeFromWorld_, scene.verticesWorld[edge.vertices[0]]);
    Vec3 bEye = TransformPoint(eyeFromWorld_, scene.verticesWorld[edge.vertices[1]]);
    if (!IsFinite(aEye) || !IsFinite(bEye) || !ClipSegment(aEye, bEye, clipPlanes_)) continue;
    const uint32_t faceNumber = edge.face == UINT32_MAX ? 0 : edge.face + 1;
    DrawLine(ProjectToCell(camera.projection, aEye), ProjectToCell(camera.projection, bEye),
             camera.projection.cellAspect, faceNumber, topLevel, depth, cells);
    ++drawn;
  }
  return drawn;
}

// Turns the face seen in each cell into a ramp glyph; returns the faces seen.
int Renderer::ShadeCells(const Scene& scene, const RenderOptions& options, CellBuffer& cells) {
  // Step 1: the faces seen, found from the cells (no pass over all faces).
  auto& faces = cells.FaceNumbers();
  faceLevels_.resize(scene.FaceCount(), -1);
  seenFaces_.clear();
  for (uint32_t faceNumber : faces) {
    if (faceNumber != 0 && faceLevels_[faceNumber - 1] == -1) {
      faceLevels_[faceNumber - 1] = 0;  // marked; restored to -1 below
      seenFaces_.push_back(faceNumber - 1);
    }
  }
  // Step 2: n.s per seen face, with n turned towards the eye, in world space.
  const Mat4& m = eyeFromWorld_;
  const Vec3 s = options.sunEye;
  const Vec3 sunWorld{m.At(0, 0) * s.x + m.At(1, 0) * s.y + m.At(2, 0) * s.z,
                      m.At(0, 1) * s.x + m.At(1, 1) * s.y + m.At(2, 1) * s.z,
                      m.At(0, 2) * s.x + m.At(1, 2) * s.y + m.At(2, 2) * s.z};
  double minDot = INFINITY, maxDot = -INFINITY;
  seenSunDots_.clear();
  for (uint32_t f : seenFaces_) {
    const double dot = Dot(scene.faceNormalsWorld[f], sunWorld) * (faceFront_[f] ? 1.0 : -1.0);
    seenSunDots_.push_back(dot);
    minDot = std::min(minDot, dot);
    maxDot = std::max(maxDot, dot);
  }
  // Step 3: levels per face, then glyphs per cell.
  for (size_t i = 0; i < seenFaces_.size(); ++i) {
    const double intensity = options.shade == ShadeMode::kContrast
                                 ? ContrastIntensity(seenSunDots_[i], minDot, maxDot, options.ambient)
                                 : LambertIntensity(seenSunDots_[i], options.ambient);
    faceLevels_[seenFaces_[i]] = static_cast<int16_t>(options.ramp.LevelFor(intensity));
  }
  if (options.method != Method::kWire) {
    auto& glyphs = cells.Glyphs();
    auto& levels = cells.Levels();
    for (size_t i = 0; i < faces.size(); ++i) {
      if (faces[i] == 0) continue;
      levels[i] = faceLevels_[faces[i] - 1];
      glyphs[i] = options.ramp.Glyph(levels[i]);
    }
  }
  for (uint32_t f : seenFaces_) faceLevels_[f] = -1;
  return static_cast<int>(seenFaces_.size());
}

}  // namespace termshade
