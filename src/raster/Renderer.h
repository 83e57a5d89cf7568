#pragma once

#include <cstdint>
#include <memory>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/ClusterStage.h"
#include "raster/DepthBuffer.h"
#include "raster/FaceStage.h"
#include "raster/FramePlan.h"
#include "raster/GlyphStage.h"
#include "raster/RayCastStage.h"
#include "raster/RenderOptions.h"
#include "raster/SampleFrame.h"
#include "raster/ShadeStage.h"
#include "raster/SurfacePassChoice.h"
#include "raster/TextureStage.h"
#include "raster/WorkerPool.h"

namespace termshade {

/// What one frame drew.
struct RenderStats {
  int trianglesDrawn = 0;  ///< triangles rasterized: facing the eye (or culling off), near a sample
  int facesVisible = 0;    ///< distinct faces seen in at least one cell
  bool byHierarchy =
      false;  ///< the surfaces were found by rays through Scene::hierarchy (RayCastStage)
};

/// The one geometry pipeline, world -> eye -> cells, for every front end:
/// each frame planned once (FramePlan), then its stages run in order.
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
  /// The buffers a frame's surface pass draws into.
  struct SurfaceBuffers {
    CellBuffer& cells;
    DepthBuffer& depth;
  };
  SurfaceBuffers BeginSurfaces(const FramePlan& plan, DepthBuffer& depth, CellBuffer& cells);
  RenderStats DrawSurfaces(const Scene& scene, const FramePlan& plan, SurfaceBuffers to);
  int DrawClusters(const Scene& scene, const FramePlan& plan, SurfaceBuffers to);
  int DrawByQuickerPass(const Scene& scene, const FramePlan& plan, SurfaceBuffers to,
                        bool& byHierarchy);
  int ShadeFaces(const Scene& scene, const FramePlan& plan, CellBuffer& surfaceCells);
  void ComposeGlyphs(const FramePlan& plan, DepthBuffer& depth, CellBuffer& cells);
  /// The pool for `threads` threads (kept between frames); none for one.
  WorkerPool* PoolFor(int threads);

  /// Several samples a cell: the frame at k x m samples a cell, row-major
  /// (drawn so when the sampled rasterizer does not serve; else filled when asked for).
  mutable CellBuffer fineCells_;
  mutable bool fineCellsCurrent_ = false;
  DepthBuffer fineDepth_;
  SampleFrame sampleFrame_;  ///< the same samples cell by cell: what the glyph stage reads
  FaceStage faceStage_;
  ClusterStage clusterStage_;
  RayCastStage rayCastStage_;
  ShadeStage shadeStage_;
  GlyphStage glyphStage_;
  TextureStage textureStage_;
  std::unique_ptr<WorkerPool> pool_;
  WorkerPool* framePool_ = nullptr;  ///< this frame's threads for the cluster pass and shading
  SurfacePassChoice passChoice_;  ///< rays or clusters, by their times (HierarchyUse::kWhenFaster)
  std::weak_ptr<const RayBvh> choiceHierarchy_;  ///< the hierarchy passChoice_ timed
  uint64_t choiceHierarchySerial_ = 0;           ///< bumped when it changes
  SampleGrid lastGrid_;
};

}  // namespace termshade
