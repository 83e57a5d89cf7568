#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/Scene.h"
#include "geometry/TriangleBvh.h"
#include "raster/CellBuffer.h"
#include "raster/ClusterStage.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "raster/WorkerPool.h"

namespace termshade {

/// The surface pass of zbuffer and cull for scenes of far more triangles
/// than samples: the scene's TriangleBvh walked from the root, skipping
/// subtrees whose faces all face away (normal cones) or whose box projects
/// onto no cell-center sample, so only the triangles near a sample are read
/// and projected; those are rasterized in scene order. Its triangles are
/// exactly those ClusterStage rasterizes (front-facing, box holding a sample,
/// the same snapped corners), so the frame and the count are bit for bit the
/// same. The walk is split in subtrees among threads, the rasterization in
/// row bands.
class HierarchyStage {
 public:
  /// True when the frame is one the stage draws exactly: one sample a cell,
  /// back faces culled, double geometry and float 1/z, and every vertex on
  /// the vertex stage's direct path (no clipping: the root's bounding sphere
  /// lies in front of twice the near distance and inside half the guard band).
  static bool Applies(const Scene& scene, const TriangleBvh& bvh, const ClusterFrame& frame);

  /// From this many triangles a sample the walk was quicker than the cluster
  /// pass on both machines measured (bench frame on spheres of 0.2M to 6M
  /// triangles at 80x24 to 400x120: 0.24x-0.30x at 3,100 a sample, 0.5x-0.6x
  /// at 1,040, 0.5x-0.7x at 780). The pass drawn first where both are timed,
  /// and where render (building before its first frame) builds a hierarchy.
  static constexpr double kFasterFromTrianglesPerSample = 700.0;
  static bool Faster(const Scene& scene, int widthSamples, int heightSamples) {
    return TrianglesPerSample(scene, widthSamples, heightSamples) >= kFasterFromTrianglesPerSample;
  }
  /// From this many triangles a sample the renderer times the walk against
  /// the cluster pass and draws by the quicker (SurfacePassChoice): the
  /// crossover on the first machine measured (about 260; the second put it
  /// near 450); below it neither machine's walk was quicker.
  static constexpr double kTriedFromTrianglesPerSample = 250.0;
  static bool WorthTrying(const Scene& scene, int widthSamples, int heightSamples) {
    return TrianglesPerSample(scene, widthSamples, heightSamples) >= kTriedFromTrianglesPerSample;
  }
  static double TrianglesPerSample(const Scene& scene, int widthSamples, int heightSamples) {
    return static_cast<double>(scene.triangles.size()) /
           (static_cast<double>(widthSamples) * heightSamples);
  }
  /// Whether frames of widthCells x heightCells drawn with `options` would
  /// walk a hierarchy of the scene, were one attached: a frame the walk
  /// serves (zbuffer, cull or auto, back faces culled, the product's
  /// geometry and depth; several samples a cell only when drawn on threads)
  /// with at least `fromTrianglesPerSample` triangles a sample of its grid
  /// (the default: the walk is worth trying). Front ends build a hierarchy
  /// only then.
  static bool WouldWalk(const Scene& scene, int widthCells, int heightCells,
                        const RenderOptions& options,
                        double fromTrianglesPerSample = kTriedFromTrianglesPerSample);

  /// Draws; returns the triangles rasterized (as ClusterStage counts them).
  int Draw(const Scene& scene, const TriangleBvh& bvh, const ClusterFrame& frame, int threads,
           DepthBuffer& depth, CellBuffer& cells);

  /// A triangle found to draw: its scene index, face number and snapped corners.
  struct Drawn {
    uint32_t triangle;
    uint32_t faceNumber;
    RasterVertex corners[3];
  };

 private:
  /// What one worker found: leaves (first triangles, the top bit set when
  /// every face is front) and their triangles to draw.
  struct Found {
    std::vector<uint32_t> leaves;
    std::vector<Drawn> drawn;
  };
  std::unique_ptr<WorkerPool> pool_;
  std::vector<uint32_t> tasks_;  ///< subtrees for the workers (node indices, the same top bit)
  std::atomic<size_t> nextTask_{0};
  std::vector<Found> perWorker_;
  std::vector<Drawn> drawn_;  ///< every worker's, in scene order where the rule needs it
};

}  // namespace termshade
