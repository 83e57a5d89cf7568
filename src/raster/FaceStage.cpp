#include "raster/FaceStage.h"

#include <algorithm>
#include <array>

#include "process/HugePages.h"
#include "raster/ClipToRaster.h"
#include "raster/VertexStage.h"

namespace termshade {

int FaceStage::Draw(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                    bool painter, DepthBuffer& depth, CellBuffer& cells) {
  ProjectVertices(scene, view, raster, painter);
  return painter ? DrawFarToNear(scene, view, raster, depth, cells)
                 : DrawInSceneOrder(scene, view, raster, depth, cells);
}

void FaceStage::ProjectVertices(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                                bool needEyeZ) {
  const size_t count = scene.verticesWorld.size();
  ResizeWithHugePages(zEye_, needEyeZ ? count : 0);
  ResizeWithHugePages(rasterVertices_, count);
  ResizeWithHugePages(outCodes_, count);
  const float maxW = termshade::ProjectVertices(
      scene.verticesWorld, view.eyeFromWorld, view.camera.projection, view.clipPlanes,
      raster.floatGeometry,
      {rasterVertices_.data(), outCodes_.data(), needEyeZ ? zEye_.data() : nullptr});
  depthEncoding_ = {raster.depthFormat, maxW > 0.0F ? 65535.0F / maxW : 1.0F};
  scanline_ = raster.scanline;
}

// Textbook painter: far to near by the sum of the vertices' eye z.
int FaceStage::DrawFarToNear(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                             DepthBuffer& depth, CellBuffer& cells) {
  painterOrder_.clear();
  for (uint32_t f = 0; f < scene.FaceCount(); ++f) {
    // The eye strictly in front of the face's plane (h < 0 in eye space).
    if (raster.cullBackFaces && !scene.facePlanesWorld[f].FacesPoint(view.eyeWorld)) continue;
    for (uint32_t i = scene.FaceTrianglesBegin(f); i < scene.FaceTrianglesBegin(f + 1); ++i) {
      const SceneTriangle& t = scene.triangles[i];
      painterOrder_.emplace_back(zEye_[t.vertices[0]] + zEye_[t.vertices[1]] + zEye_[t.vertices[2]],
                                 i);
    }
  }
  std::sort(painterOrder_.begin(), painterOrder_.end());
  int drawn = 0;
  for (const auto& [zSum, i] : painterOrder_) {
    drawn += DrawTriangle(scene, view, i, raster.rule, depth, cells);
  }
  return drawn;
}

// Face by face: a face behind its plane is skipped whole, its triangles never read.
int FaceStage::DrawInSceneOrder(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                                DepthBuffer& depth, CellBuffer& cells) {
  int drawn = 0;
  const bool cull = raster.cullBackFaces;
  const DepthRule rule = raster.rule;
  // The hot loop: plain pointers, the in-view case inline, the rest out of line.
  const FacePlane* const planes = scene.facePlanesWorld.data();
  const uint32_t* const starts =
      scene.faceTriangleStarts.empty() ? nullptr : scene.faceTriangleStarts.data();
  const SceneTriangle* const triangles = scene.triangles.data();
  const RasterVertex* const projected = rasterVertices_.data();
  const uint8_t* const codes = outCodes_.data();
  const Vec3 eyeWorld = view.eyeWorld;
  const int width = cells.WidthCells(), height = cells.HeightCells();
  const uint32_t faceCount = static_cast<uint32_t>(scene.FaceCount());
  for (uint32_t f = 0; f < faceCount; ++f) {
    if (cull && !planes[f].FacesPoint(eyeWorld)) continue;
    const uint32_t end = starts != nullptr ? starts[f + 1] : f + 1;
    for (uint32_t i = starts != nullptr ? starts[f] : f; i < end; ++i) {
      const auto& v = triangles[i].vertices;
      if ((codes[v[0]] | codes[v[1]] | codes[v[2]]) != 0) {
        drawn += DrawTriangle(scene, view, i, rule, depth, cells);
        continue;
      }
      const RasterVertex& a = projected[v[0]];
      const RasterVertex& b = projected[v[1]];
      const RasterVertex& c = projected[v[2]];
      if (!MayCoverSample(a, b, c, width, height)) continue;
      Rasterize(a, b, c, f + 1, rule, depth, cells);
      ++drawn;
    }
  }
  return drawn;
}

int FaceStage::DrawTriangle(const Scene& scene, const FrameView& view, uint32_t triangle,
                            DepthRule rule, DepthBuffer& depth, CellBuffer& cells) {
  const SceneTriangle& t = scene.triangles[triangle];
  const uint32_t faceNumber = scene.TriangleFace(triangle) + 1;
  const unsigned codes[3] = {outCodes_[t.vertices[0]], outCodes_[t.vertices[1]],
                             outCodes_[t.vertices[2]]};
  // Fast path: wholly inside the near plane and the guard band.
  if ((codes[0] | codes[1] | codes[2]) == 0) {
    const RasterVertex& a = rasterVertices_[t.vertices[0]];
    const RasterVertex& b = rasterVertices_[t.vertices[1]];
    const RasterVertex& c = rasterVertices_[t.vertices[2]];
    if (!MayCoverSample(a, b, c, cells.WidthCells(), cells.HeightCells())) return 0;
    Rasterize(a, b, c, faceNumber, rule, depth, cells);
    return 1;
  }
  if ((codes[0] & codes[1] & codes[2]) != 0) return 0;
  std::array<RasterVertex, kClippedCornersMax> projected{};
  const size_t count = ClipToRaster(scene, triangle, view.eyeFromWorld, view.clipPlanes,
                                    view.camera.projection, projected);
  if (count < 3) return 0;
  // The clipped polygon is convex: a fan from its first corner covers it.
  for (size_t i = 1; i + 1 < count; ++i) {
    Rasterize(projected[0], projected[i], projected[i + 1], faceNumber, rule, depth, cells);
  }
  return 1;
}

void FaceStage::Rasterize(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                          uint32_t faceNumber, DepthRule rule, DepthBuffer& depth,
                          CellBuffer& cells) const {
  if (scanline_) {
    RasterizeTriangleScanline(a, b, c, faceNumber, rule, depth, cells);
  } else {
    RasterizeTriangle(a, b, c, faceNumber, rule, depth, cells, depthEncoding_);
  }
}

}  // namespace termshade
