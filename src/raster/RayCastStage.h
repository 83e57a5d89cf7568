#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "geometry/RayBvh.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/ClusterStage.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "raster/WorkerPool.h"

namespace termshade {

struct TileEntries;

/// The surface pass of zbuffer and cull for scenes of far more triangles
/// than samples: each cell-center sample finds, through the scene's RayBvh,
/// the triangles that may cover it (the node boxes widened by the snapping's
/// 1/512 cell and rounding), near to far, and decides each exactly as the
/// rasterizer does (the same snapped corners, edge functions, top-left rule
/// and float 1/z). The nearest wins (zbuffer: lower face on equal depth) or
/// the last in scene order (cull), so every cell's face and depth are bit for
/// bit those of ClusterStage. Samples are handed out in tiles, one at a time
/// to any thread; each tile's rays start below the subtrees its pyramid
/// reaches (RayTileFrontier).
class RayCastStage {
 public:
  RayCastStage();
  ~RayCastStage();
  RayCastStage(const RayCastStage&) = delete;
  RayCastStage& operator=(const RayCastStage&) = delete;

  /// One sample's walk in progress (RayCastStage.cpp).
  struct Lane;
  /// Walks each worker keeps going at once, stepped in turn.
  static constexpr int kLanes = 8;
  /// Samples are handed out in tiles of this many columns and rows; each
  /// tile's rays start below the subtrees its pyramid reaches.
  static constexpr int kTileCols = 8;
  static constexpr int kTileRows = 4;

  /// True when the frame is one the stage draws exactly: one sample a cell,
  /// back faces culled, double geometry and float 1/z, and every vertex on
  /// the vertex stage's direct path (no clipping: the root box lies in
  /// front of twice the near distance and inside half the guard band).
  static bool Applies(const Scene& scene, const RayBvh& bvh, const ClusterFrame& frame);

  /// From this many triangles a sample the rays were quicker than the
  /// cluster pass (bench frame): the pass drawn first where both are timed,
  /// and where render (building before its first frame) builds a hierarchy.
  static constexpr double kFasterFromTrianglesPerSample = 150.0;
  static bool Faster(const Scene& scene, int widthSamples, int heightSamples) {
    return TrianglesPerSample(scene, widthSamples, heightSamples) >= kFasterFromTrianglesPerSample;
  }
  /// From this many triangles a sample the renderer times the rays against
  /// the cluster pass and draws by the quicker (SurfacePassChoice); below it
  /// the rays were never quicker.
  static constexpr double kTriedFromTrianglesPerSample = 50.0;
  static bool WorthTrying(const Scene& scene, int widthSamples, int heightSamples) {
    return TrianglesPerSample(scene, widthSamples, heightSamples) >= kTriedFromTrianglesPerSample;
  }
  static double TrianglesPerSample(const Scene& scene, int widthSamples, int heightSamples) {
    return static_cast<double>(scene.triangles.size()) /
           (static_cast<double>(widthSamples) * heightSamples);
  }
  /// Whether frames of widthCells x heightCells drawn with `options` would
  /// cast rays through a hierarchy of the scene, were one attached: a frame
  /// the stage serves (zbuffer, cull or auto, back faces culled, the
  /// product's geometry and depth; several samples a cell only when drawn on
  /// threads) with at least `fromTrianglesPerSample` triangles a sample of
  /// its grid (the default: the rays are worth trying). Front ends build a
  /// hierarchy only then.
  static bool WouldCast(const Scene& scene, int widthCells, int heightCells,
                        const RenderOptions& options,
                        double fromTrianglesPerSample = kTriedFromTrianglesPerSample);

  /// Draws, on the pool's workers when given; returns how many (sample,
  /// triangle) pairs were found covering.
  int Draw(const Scene& scene, const RayBvh& bvh, const ClusterFrame& frame, WorkerPool* pool,
           DepthBuffer& depth, CellBuffer& cells);

 private:
  std::atomic<int> nextTile_{0};
  std::vector<int> coveredPerWorker_;
  std::unique_ptr<Lane[]> lanes_;  ///< kLanes a worker
  size_t laneCount_ = 0;
  std::unique_ptr<TileEntries[]> tileEntries_;  ///< one a worker
  size_t tileEntriesCount_ = 0;
};

}  // namespace termshade
