#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/ClipPolygon.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/ClusterStage.h"
#include "raster/DepthBuffer.h"
#include "raster/GlyphStage.h"
#include "raster/RayCastStage.h"
#include "raster/RenderOptions.h"
#include "raster/SampleFrame.h"
#include "raster/ShadeStage.h"
#include "raster/SurfacePassChoice.h"
#include "raster/TriangleRasterizer.h"
#include "raster/WorkerPool.h"

namespace termshade {

/// What one frame drew.
struct RenderStats {
  int trianglesDrawn = 0;  ///< triangles rasterized: facing the eye (or culling off), near a sample
  int facesVisible = 0;    ///< distinct faces seen in at least one cell
  bool byHierarchy =
      false;  ///< the surfaces were found by rays through Scene::hierarchy (RayCastStage)
};

/// The method actually drawn: auto becomes cull or zbuffer for the scene.
Method ResolvedMethod(const Scene& scene, Method method);

/// The camera whose one-sample cells are the samples of `camera`'s cells on a
/// k x m grid: u' = k u, v' = m v (d and cx scale by k, cy by m, the aspect by k / m).
Camera SampleCamera(const Camera& camera, SampleGrid grid);

/// The one geometry pipeline, world -> eye -> cells, for every front end.
/// Keeps per-frame scratch arrays between frames, so a steady frame loop
/// does not allocate.
class Renderer {
 public:
  /// Draws the scene into cells and depth, which must already have the frame's size.
  RenderStats Render(const Scene& scene, const Camera& camera, const RenderOptions& options,
                     DepthBuffer& depth, CellBuffer& cells);

  /// The last frame's samples when it had several a cell, as a one-sample
  /// frame of faces at grid.across x grid.down times the cells; otherwise the
  /// frame itself is the samples.
  const CellBuffer& Samples() const;
  SampleGrid LastSampleGrid() const { return lastGrid_; }

 private:
  RenderStats RenderSampled(const Scene& scene, const Camera& camera, const RenderOptions& options,
                            DepthBuffer& depth, CellBuffer& cells);
  RenderStats DrawSampleFrame(const Scene& scene, const Camera& fine, const RenderOptions& single);
  void TransformVertices(const Scene& scene, const Camera& camera, const RenderVariant& variant,
                         bool needEyeZ);
  bool FaceIsFront(const Scene& scene, uint32_t face) const;
  void Rasterize(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                 uint32_t faceNumber, DepthRule rule, DepthBuffer& depth, CellBuffer& cells) const;
  int DrawTriangle(const Scene& scene, const Camera& camera, uint32_t triangle, DepthRule rule,
                   DepthBuffer& depth, CellBuffer& cells);
  int DrawSurfaces(const Scene& scene, const Camera& camera, const RenderOptions& options,
                   DepthBuffer& depth, CellBuffer& cells);
  int DrawClusters(const Scene& scene, const Camera& camera, const RenderOptions& options,
                   DepthBuffer& depth, CellBuffer& cells, TriangleSink* sink = nullptr);
  int DrawByQuickerPass(const Scene& scene, const std::shared_ptr<const RayBvh>& bvh,
                        const ClusterFrame& frame, int threads, DepthBuffer& depth,
                        CellBuffer& cells);
  int DrawEdges(const Scene& scene, const Camera& camera, const RenderOptions& options,
                DepthBuffer& depth, CellBuffer& cells);
  /// The pool for `threads` threads (kept between frames); none for one.
  WorkerPool* PoolFor(int threads);

  ViewClipPlanes clipPlanes_{};
  Mat4 eyeFromWorld_;
  Vec3 eyeWorld_;
  DepthEncoding depthEncoding_;
  bool scanline_ = false;
  float maxW_ = 0.0F;
  /// Several samples a cell: the frame at k x m samples a cell, row-major
  /// (drawn so when the sampled rasterizer does not serve; else filled when asked for).
  mutable CellBuffer fineCells_;
  mutable bool fineCellsCurrent_ = false;
  DepthBuffer fineDepth_;
  SampleFrame sampleFrame_;  ///< the same samples cell by cell: what the glyph stage reads
  GlyphStage glyphStage_;
  ShadeStage shadeStage_;
  std::unique_ptr<WorkerPool> pool_;
  WorkerPool* framePool_ = nullptr;  ///< this frame's threads for the surface pass and shading
  ClusterStage clusterStage_;
  RayCastStage rayCastStage_;
  bool drewByHierarchy_ = false;  ///< the last DrawClusters cast rays through the hierarchy
  SurfacePassChoice passChoice_;  ///< rays or clusters, by their times (HierarchyUse::kWhenFaster)
  std::weak_ptr<const RayBvh> choiceHierarchy_;  ///< the hierarchy passChoice_ timed
  uint64_t choiceHierarchySerial_ = 0;           ///< bumped when it changes
  SampleGrid lastGrid_;
  std::vector<double> zEye_;  ///< eye z per vertex, for the painter's sort
  std::vector<RasterVertex> rasterVertices_;
  std::vector<uint8_t> outCodes_;
  std::vector<std::pair<double, uint32_t>> painterOrder_;
};

}  // namespace termshade
