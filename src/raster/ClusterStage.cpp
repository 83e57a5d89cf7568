#include "raster/ClusterStage.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "geometry/FixedRange.h"
#include "geometry/ViewingTransform.h"
#include "process/HugePages.h"
#include "raster/ClipToRaster.h"
#include "raster/FixedPoint.h"
#include "raster/VertexStage.h"

namespace termshade {
namespace {

// False when no vertex of the cluster can give a triangle a sample to
// cover: its bounding sphere lies wholly outside one clip plane (every
// triangle then has a shared out-code bit), or lies where every vertex is
// projected directly and its projected box holds no cell-center sample.
// Margins cover rounding: 1e-9 relative, 0.01 cell on the screen.
bool SphereMayCover(const SceneCluster& cluster, const ClusterFrame& frame, int width, int height) {
  const Vec3 c = TransformPoint(frame.eyeFromWorld, cluster.centerWorld);
  const double r = cluster.radius;
  const double margin = 1e-9 * (Length(c) + r);
  for (const ClipPlane& plane : frame.clipPlanes) {
    if (plane.Distance(c) < -r * Length(plane.normal) - margin * (1.0 + Length(plane.normal))) {
      return false;
    }
  }
  // Every vertex takes the vertex stage's direct path (VertexStage.cpp):
  // twice the near distance in front, half the guard band across.
  const Projection& proj = frame.projection;
  const double nearZ = 2.0 * -frame.clipPlanes[0].offset;
  const double depthNear = -c.z - r, depthFar = -c.z + r;
  if (!(depthNear > nearZ * (1.0 + 1e-9) + margin)) return true;
  auto range = [&](double center, double& low, double& high) {
    const double lo = center - r, hi = center + r;
    high = hi > 0.0 ? hi / depthNear : hi / depthFar;
    low = lo < 0.0 ? lo / depthNear : lo / depthFar;
  };
  double xLow = 0, xHigh = 0, yLow = 0, yHigh = 0;
  range(c.x, xLow, xHigh);
  range(c.y, yLow, yHigh);
  const double vScale = proj.d / proj.cellAspect;
  const double xLimit = 0.5 * (kClipRangeCells - proj.cx) * (1.0 - 1e-9);
  const double yLimit = 0.5 * (kClipRangeCells - proj.cy) * (1.0 - 1e-9);
  if (std::max(-xLow, xHigh) * proj.d > xLimit || std::max(-yLow, yHigh) * vScale > yLimit) {
    return true;
  }
  constexpr double kScreenMargin = 0.01;
  return RangeHoldsSample(proj.cx + proj.d * xLow - kScreenMargin,
                          proj.cx + proj.d * xHigh + kScreenMargin, width) &&
         RangeHoldsSample(proj.cy - vScale * yHigh - kScreenMargin,
                          proj.cy - vScale * yLow + kScreenMargin, height);
}

bool ClusterMayShow(const SceneCluster& cluster, const ClusterFrame& frame, int width, int height,
                    bool& allFront) {
  allFront = !frame.cullBackFaces;
  if (!frame.clusterCulling) return true;
  if (frame.cullBackFaces) {
    const ClusterFacing facing = FacingOf(cluster, frame.eyeWorld);
    if (facing == ClusterFacing::kAway) return false;
    allFront = facing == ClusterFacing::kToward;
  }
  // Float geometry rounds beyond the sphere test's margins: faces only.
  return frame.floatGeometry || SphereMayCover(cluster, frame, width, height);
}

// One cluster's triangles in order, each that may cover a sample handed to
// emit(a, b, c, faceNumber) (a clipped one as its fan). allFront: the cone
// showed every face front-facing. Returns the triangles counted as drawn.
template <typename Emit>
int SetUpCluster(const Scene& scene, const SceneCluster& cluster, const ClusterFrame& frame,
                 bool allFront, const RasterVertex* raster, const uint8_t* codes, int width,
                 int height, Emit&& emit) {
  const SceneTriangle* const triangles = scene.triangles.data();
  const uint32_t* const faceOf = scene.triangleFaces.empty() ? nullptr : scene.triangleFaces.data();
  const FacePlane* const planes = scene.facePlanesWorld.data();
  int drawn = 0;
  uint32_t lastFace = UINT32_MAX;
  bool front = true;
  for (uint32_t t = cluster.firstTriangle; t < cluster.triangleEnd; ++t) {
    const uint32_t face = faceOf != nullptr ? faceOf[t] : t;
    if (!allFront && face != lastFace) {
      lastFace = face;
      front = planes[face].FacesPoint(frame.eyeWorld);
    }
    if (!front) continue;
    const auto& v = triangles[t].vertices;
    if ((codes[v[0]] | codes[v[1]] | codes[v[2]]) != 0) {
      if ((codes[v[0]] & codes[v[1]] & codes[v[2]]) != 0) continue;
      std::array<RasterVertex, kClippedCornersMax> polygon{};
      const size_t count =
          ClipToRaster(scene, t, frame.eyeFromWorld, frame.clipPlanes, frame.projection, polygon);
      if (count < 3) continue;
      for (size_t i = 1; i + 1 < count; ++i) emit(polygon[0], polygon[i], polygon[i + 1], face + 1);
      ++drawn;
      continue;
    }
    const RasterVertex& a = raster[v[0]];
    const RasterVertex& b = raster[v[1]];
    const RasterVertex& c = raster[v[2]];
    if (!MayCoverSample(a, b, c, width, height)) continue;
    emit(a, b, c, face + 1);
    ++drawn;
  }
  return drawn;
}

// Vertices [first, end) transformed and projected into raster and codes.
void ProjectRange(const Scene& scene, const ClusterFrame& frame, size_t first, size_t end,
                  RasterVertex* raster, uint8_t* codes) {
  ProjectVertices(std::span<const Vec3>(scene.verticesWorld).subspan(first, end - first),
                  frame.eyeFromWorld, frame.projection, frame.clipPlanes, frame.floatGeometry,
                  {raster + first, codes + first, nullptr});
}

}  // namespace

bool ClusterStage::Usable(const Scene& scene) {
  const auto& clusters = scene.clusters.clusters;
  if (scene.triangles.empty()) return clusters.empty();
  return !clusters.empty() && clusters.front().firstTriangle == 0 &&
         clusters.back().triangleEnd == scene.triangles.size();
}

int ClusterStage::Draw(const Scene& scene, const ClusterFrame& frame, WorkerPool* pool,
                       DepthBuffer& depth, CellBuffer& cells) {
  if (pool != nullptr && pool->Workers() > 1 && !frame.scanline && frame.sink == nullptr &&
      scene.triangles.size() >= frame.threadsFromTriangles) {
    return DrawThreaded(scene, frame, *pool, depth, cells);
  }
  const int width = cells.WidthCells(), height = cells.HeightCells();
  ResizeWithHugePages(raster_, scene.verticesWorld.size());
  ResizeWithHugePages(codes_, scene.verticesWorld.size());
  ProjectRange(scene, frame, 0, raster_.size(), raster_.data(), codes_.data());
  int drawn = 0;
  auto rasterize = [&](const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                       uint32_t faceNumber) {
    if (frame.sink != nullptr) {
      frame.sink->Draw(a, b, c, faceNumber);
    } else if (frame.scanline) {
      RasterizeTriangleScanline(a, b, c, faceNumber, frame.rule, depth, cells);
    } else {
      RasterizeTriangle(a, b, c, faceNumber, frame.rule, depth, cells, frame.depthEncoding);
    }
  };
  for (const SceneCluster& cluster : scene.clusters.clusters) {
    bool allFront = false;
    if (!ClusterMayShow(cluster, frame, width, height, allFront)) continue;
    drawn += SetUpCluster(scene, cluster, frame, allFront, raster_.data(), codes_.data(), width,
                          height, rasterize);
  }
  return drawn;
}

int ClusterStage::DrawThreaded(const Scene& scene, const ClusterFrame& frame, WorkerPool& pool,
                               DepthBuffer& depth, CellBuffer& cells) {
  const int threads = pool.Workers();
  const int width = cells.WidthCells(), height = cells.HeightCells();
  const auto& clusters = scene.clusters.clusters;
  // Many more runs than threads: which clusters face the eye is uneven along the scene order.
  const int runs = static_cast<int>(std::min<size_t>(clusters.size(), size_t{16} * threads));
  const int bands = std::min(height, 4 * threads);
  const int rowsPerBand = (height + bands - 1) / bands;
  ResizeWithHugePages(raster_, scene.verticesWorld.size());
  ResizeWithHugePages(codes_, scene.verticesWorld.size());
  bins_.resize(static_cast<size_t>(runs) * bands);
  for (auto& bin : bins_) bin.clear();
  drawnPerRun_.assign(runs, 0);

  // Step 1: the vertices, a range per thread.
  auto project = [&](int worker) {
    const size_t count = raster_.size();
    ProjectRange(scene, frame, count * worker / threads, count * (worker + 1) / threads,
                 raster_.data(), codes_.data());
  };
  pool.Run(project);

  // Step 2: runs of clusters set up in parallel, triangles binned by row band.
  nextTask_ = 0;
  auto setUp = [&](int) {
    for (int run = nextTask_++; run < runs; run = nextTask_++) {
      const size_t first = clusters.size() * run / runs, end = clusters.size() * (run + 1) / runs;
      std::vector<Binned>* const runBins = bins_.data() + static_cast<size_t>(run) * bands;
      auto bin = [&](const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                     uint32_t faceNumber) {
        const int32_t minY = std::min(a.y, std::min(b.y, c.y));
        const int32_t maxY = std::max(a.y, std::max(b.y, c.y));
        const int firstRow = std::max(0, (minY + kFixedHalf - 1) >> kSubCellBits);
        const int lastRow = std::min(height - 1, (maxY - kFixedHalf) >> kSubCellBits);
        for (int band = firstRow / rowsPerBand;
             band <= lastRow / rowsPerBand && firstRow <= lastRow; ++band) {
          runBins[band].push_back({a, b, c, faceNumber});
        }
      };
      int drawn = 0;
      for (size_t k = first; k < end; ++k) {
        bool allFront = false;
        if (!ClusterMayShow(clusters[k], frame, width, height, allFront)) continue;
        drawn += SetUpCluster(scene, clusters[k], frame, allFront, raster_.data(), codes_.data(),
                              width, height, bin);
      }
      drawnPerRun_[run] = drawn;
    }
  };
  pool.Run(setUp);

  // Step 3: each band drawn by one thread, the runs in scene order.
  nextTask_ = 0;
  auto drawBands = [&](int) {
    for (int band = nextTask_++; band < bands; band = nextTask_++) {
      const RowRange rows{band * rowsPerBand, std::min(height, (band + 1) * rowsPerBand)};
      for (int run = 0; run < runs; ++run) {
        for (const Binned& t : bins_[static_cast<size_t>(run) * bands + band]) {
          RasterizeTriangle(t.a, t.b, t.c, t.faceNumber, frame.rule, depth, cells,
                            frame.depthEncoding, rows);
        }
      }
    }
  };
  pool.Run(drawBands);
  int drawn = 0;
  for (int d : drawnPerRun_) drawn += d;
  return drawn;
}

}  // namespace termshade
