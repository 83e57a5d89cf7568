#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/ClipPolygon.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "raster/TriangleRasterizer.h"

namespace termshade {

/// What one frame drew.
struct RenderStats {
  int trianglesDrawn = 0;  ///< triangles sent to the rasterizer (after culling and clipping)
  int facesVisible = 0;    ///< distinct faces seen in at least one cell
};

/// The one geometry pipeline, world -> eye -> cells, for every front end.
/// Keeps per-frame scratch arrays between frames, so a steady frame loop
/// does not allocate.
class Renderer {
 public:
  /// Draws the scene into cells and depth, which must already have the frame's size.
  RenderStats Render(const Scene& scene, const Camera& camera, const RenderOptions& options,
                     DepthBuffer& depth, CellBuffer& cells);

 private:
  void TransformVertices(const Scene& scene, const Camera& camera);
  void ClassifyFaces(const Scene& scene, const Camera& camera, const RenderOptions& options);
  int DrawTriangle(const Scene& scene, const Camera& camera, uint32_t triangle, DepthRule rule,
                   DepthBuffer& depth, CellBuffer& cells);
  int DrawSurfaces(const Scene& scene, const Camera& camera, const RenderOptions& options,
                   DepthBuffer& depth, CellBuffer& cells);
  int DrawEdges(const Scene& scene, const Camera& camera, const RenderOptions& options,
                DepthBuffer& depth, CellBuffer& cells);
  int ShadeCells(const RenderOptions& options, CellBuffer& cells);

  ViewClipPlanes clipPlanes_{};
  std::vector<Vec3> verticesEye_;
  std::vector<RasterVertex> rasterVertices_;
  std::vector<uint8_t> outCodes_;
  std::vector<uint8_t> faceDrawn_;      ///< per face: drawn this frame (front, or culling off)
  std::vector<float> faceSunDots_;      ///< per face: n.s with n turned towards the eye
  std::vector<int16_t> faceLevels_;     ///< per face: ramp level this frame
  std::vector<uint8_t> faceSeen_;
  std::vector<std::pair<double, uint32_t>> painterOrder_;
};

}  // namespace termshade
