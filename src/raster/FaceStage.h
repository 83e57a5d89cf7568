#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/FramePlan.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {

/// The plain surface pass, one thread: every vertex projected (VertexStage),
/// then the triangles face by face in scene order, or (painter) far to near
/// by the sum of their vertices' eye z; a face behind its plane is skipped
/// whole when back faces are culled. The reference the cluster pass is
/// compared with, and the pass of painter and of the 16-bit depth variant.
/// Keeps its per-vertex arrays between frames.
class FaceStage {
 public:
  /// Draws; returns the triangles rasterized (facing the eye, near a sample).
  int Draw(const Scene& scene, const FrameView& view, const RasterPlan& raster, bool painter,
           DepthBuffer& depth, CellBuffer& cells);

 private:
  void ProjectVertices(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                       bool needEyeZ);
  int DrawInSceneOrder(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                       DepthBuffer& depth, CellBuffer& cells);
  int DrawFarToNear(const Scene& scene, const FrameView& view, const RasterPlan& raster,
                    DepthBuffer& depth, CellBuffer& cells);
  int DrawTriangle(const Scene& scene, const FrameView& view, uint32_t triangle, DepthRule rule,
                   DepthBuffer& depth, CellBuffer& cells);
  void Rasterize(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                 uint32_t faceNumber, DepthRule rule, DepthBuffer& depth, CellBuffer& cells) const;

  DepthEncoding depthEncoding_;  ///< this frame's (the 16-bit scale from its nearest vertex)
  bool scanline_ = false;
  std::vector<double> zEye_;  ///< eye z per vertex, for the painter's sort
  std::vector<RasterVertex> rasterVertices_;
  std::vector<uint8_t> outCodes_;
  std::vector<std::pair<double, uint32_t>> painterOrder_;
};

}  // namespace termshade
