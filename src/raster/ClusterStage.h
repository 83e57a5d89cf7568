#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/ClipPolygon.h"
#include "geometry/Mat4.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/TriangleRasterizer.h"
#include "raster/WorkerPool.h"

namespace termshade {

/// Takes a frame's triangles in draw order in place of the rasterizer.
class TriangleSink {
 public:
  virtual void Draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                    uint32_t faceNumber) = 0;

 protected:
  ~TriangleSink() = default;
};

/// What a cluster-by-cluster frame needs that is fixed for the frame.
struct ClusterFrame {
  Projection projection;
  Mat4 eyeFromWorld;
  ViewClipPlanes clipPlanes{};
  Vec3 eyeWorld;
  DepthEncoding depthEncoding;
  DepthRule rule = DepthRule::kNearestWins;
  bool cullBackFaces = true;   ///< per face: skip faces whose plane faces away
  bool clusterCulling = true;  ///< per cluster: skip runs that face away or cover no sample
  bool floatGeometry = false;
  bool scanline = false;            ///< the scanline variant: one thread only
  size_t threadsFromTriangles = 0;  ///< fewer triangles: one thread draws
  TriangleSink* sink = nullptr;     ///< set: the triangles go to it, on one thread
};

/// The surface pass of zbuffer and cull: every vertex transformed, then the
/// triangles cluster by cluster in scene order, whole clusters skipped when
/// they face away or cover no sample. With several threads the vertices are
/// split in ranges, runs of clusters are set up in parallel into per-(run,
/// row band) bins, then each band is drawn by one thread walking the runs in
/// order: every sample sees the triangles in the single-thread order, so the
/// frame is bit for bit the same.
class ClusterStage {
 public:
  /// True when the scene carries clusters for all its triangles.
  static bool Usable(const Scene& scene);

  /// Draws, on the pool's workers when given (big scenes without a sink);
  /// returns the triangles rasterized (as the face-by-face loop counts them).
  int Draw(const Scene& scene, const ClusterFrame& frame, WorkerPool* pool, DepthBuffer& depth,
           CellBuffer& cells);

 private:
  struct Binned {
    RasterVertex a, b, c;
    uint32_t faceNumber;
  };

  int DrawThreaded(const Scene& scene, const ClusterFrame& frame, WorkerPool& pool,
                   DepthBuffer& depth, CellBuffer& cells);

  std::vector<RasterVertex> raster_;  ///< per scene vertex, this frame
  std::vector<uint8_t> codes_;
  std::vector<std::vector<Binned>> bins_;  ///< [run * bands + band]
  std::vector<int> drawnPerRun_;
  std::atomic<int> nextTask_{0};
};

}  // namespace termshade
