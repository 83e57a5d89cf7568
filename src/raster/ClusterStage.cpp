#include "raster/ClusterStage.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "geometry/FixedRange.h"
#include "geometry/ViewingTransform.h"
#include "raster/FixedPoint.h"
#include "raster/VertexStage.h"

namespace termshade {
namespace {

// Sample columns (or rows) whose centers k + 0.5 lie in [low, high], clipped to [0, limit).
// Callers keep |low|, |high| within the guard band: the casts are exact ceil and floor.
bool HoldsSample(double low, double high, int limit) {
  const double x = low - 0.5, y = high - 0.5;
  const auto tx = static_cast<int32_t>(x), ty = static_cast<int32_t>(y);
  const int32_t first = std::max(0, tx + static_cast<int32_t>(tx < x));
  const int32_t last = std::min(limit - 1, ty - static_cast<int32_t>(ty > y));
  return first <= last;
}

// What a bounding sphere's projection shows: no cell-center sample, maybe
// one, or nothing known (not every point of it takes the direct path).
enum class SphereOnScreen { kNoSample, kMayCover, kUnknown };

// The per-frame constants of the sphere tests (clusters and groups).
struct SphereTest {
  Mat4 eyeFromWorld;
  std::array<double, std::tuple_size_v<ViewClipPlanes>> planeLengths{};  ///< |normal| of each clip plane
  double nearZ, d, vScale, cx, cy, xLimit, yLimit;
  int width, height;

  SphereTest(const ClusterFrame& frame, int widthCells, int heightCells)
      : eyeFromWorld(frame.eyeFromWorld),
        nearZ(2.0 * -frame.clipPlanes[0].offset),
        d(frame.projection.d),
        vScale(frame.projection.d / frame.projection.cellAspect),
        cx(frame.projection.cx),
        cy(frame.projection.cy),
        xLimit(0.5 * (kClipRangeCells - frame.projection.cx) * (1.0 - 1e-9)),
        yLimit(0.5 * (kClipRangeCells - frame.projection.cy) * (1.0 - 1e-9)),
        width(widthCells),
        height(heightCells) {
    for (size_t i = 0; i < planeLengths.size(); ++i) {
      planeLengths[i] = Length(frame.clipPlanes[i].normal);
    }
  }

  // c: the center in eye space. Every vertex inside takes the vertex stage's
  // direct path (VertexStage.cpp) when the sphere lies twice the near
  // distance in front and within half the guard band across; then its
  // snapped position lies in the projected box (0.01 cell margin).
  SphereOnScreen Project(Vec3 c, double r) const {
    // |x| + |y| + |z| >= |c|: a margin at least the one of the cluster test.
    const double margin = 1e-9 * (std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z) + r);
    const double depthNear = -c.z - r, depthFar = -c.z + r;
    if (!(depthNear > nearZ * (1.0 + 1e-9) + margin)) return SphereOnScreen::kUnknown;
    // Products with the reciprocals round differently from the quotients by
    // far less than the screen margin.
    const double inverseNear = 1.0 / depthNear, inverseFar = 1.0 / depthFar;
    auto range = [&](double center, double& low, double& high) {
      const double lo = center - r, hi = center + r;
      high = hi * (hi > 0.0 ? inverseNear : inverseFar);
      low = lo * (lo < 0.0 ? inverseNear : inverseFar);
    };
    double xLow = 0, xHigh = 0, yLow = 0, yHigh = 0;
    range(c.x, xLow, xHigh);
    range(c.y, yLow, yHigh);
    if (!(std::max(-xLow, xHigh) * d <= xLimit && std::max(-yLow, yHigh) * vScale <= yLimit)) {
      return SphereOnScreen::kUnknown;
    }
    constexpr double kScreenMargin = 0.01;
    return HoldsSample(cx + d * xLow - kScreenMargin, cx + d * xHigh + kScreenMargin, width) &&
                   HoldsSample(cy - vScale * yHigh - kScreenMargin,
                               cy - vScale * yLow + kScreenMargin, height)
               ? SphereOnScreen::kMayCover
               : SphereOnScreen::kNoSample;
  }

  // A group of a cluster whose sphere projected on the direct path.
  bool GroupMayCover(const ClusterGroup& group) const {
    const Vec3 center{group.center[0], group.center[1], group.center[2]};
    return Project(TransformPoint(eyeFromWorld, center), group.radius) !=
           SphereOnScreen::kNoSample;
  }
};

// False when no vertex of the cluster can give a triangle a sample to
// cover: its bounding sphere lies wholly outside one clip plane (every
// triangle then has a shared out-code bit), or its projection holds no
// cell-center sample. Margins cover rounding: 1e-9 relative.
SphereOnScreen ClusterOnScreen(const SceneCluster& cluster, const ClusterFrame& frame,
                               const SphereTest& test) {
  const Vec3 c = TransformPoint(frame.eyeFromWorld, cluster.centerWorld);
  const double r = cluster.radius;
  const double margin = 1e-9 * (Length(c) + r);
  for (size_t i = 0; i < frame.clipPlanes.size(); ++i) {
    const double length = test.planeLengths[i];
    if (frame.clipPlanes[i].Distance(c) < -r * length - margin * (1.0 + length)) {
      return SphereOnScreen::kNoSample;
    }
  }
  return test.Project(c, r);
}

// Whether the cluster may show; allFront: the cone showed every face
// front-facing; testGroups: its groups' spheres may be tested too.
bool ClusterMayShow(const SceneCluster& cluster, const ClusterFrame& frame,
                    const SphereTest& test, bool& allFront, bool& testGroups) {
  allFront = !frame.cullBackFaces;
  testGroups = false;
  if (!frame.clusterCulling) return true;
  if (frame.cullBackFaces) {
    const ClusterFacing facing = FacingOf(cluster, frame.eyeWorld);
    if (facing == ClusterFacing::kAway) return false;
    allFront = facing == ClusterFacing::kToward;
  }
  // Float geometry rounds beyond the sphere test's margins: faces only.
  if (frame.floatGeometry) return true;
  const SphereOnScreen shown = ClusterOnScreen(cluster, frame, test);
  testGroups = shown == SphereOnScreen::kMayCover;
  return shown != SphereOnScreen::kNoSample;
}

RasterVertex ToRaster(const CellPoint& p) {
  return {SnapToFixed(p.u), SnapToFixed(p.v), static_cast<float>(p.w)};
}

// A triangle crossing a clip plane: clipped in eye space from the world
// corners, projected; returns the polygon's corner count (< 3: nothing).
size_t ClipToRaster(const Scene& scene, const ClusterFrame& frame, uint32_t triangle,
                    std::array<RasterVertex, 10>& projected) {
  const SceneTriangle& t = scene.triangles[triangle];
  const std::array<Vec3, 3> cornersEye{
      TransformPoint(frame.eyeFromWorld, scene.verticesWorld[t.vertices[0]]),
      TransformPoint(frame.eyeFromWorld, scene.verticesWorld[t.vertices[1]]),
      TransformPoint(frame.eyeFromWorld, scene.verticesWorld[t.vertices[2]])};
  if (!IsFinite(cornersEye[0]) || !IsFinite(cornersEye[1]) || !IsFinite(cornersEye[2])) return 0;
  ClippedPolygon clipped;
  ClipTriangle(cornersEye, frame.clipPlanes, clipped);
  if (clipped.count < 3) return 0;
  for (size_t i = 0; i < clipped.count; ++i) {
    projected[i] = ToRaster(ProjectToCell(frame.projection, clipped.corners[i]));
  }
  return clipped.count;
}

// A cluster's distinct vertices, projected when a triangle first needs them.
struct ClusterVertices {
  static constexpr size_t kMax = 3 * SceneClusters::kMaxTriangles;
  std::array<RasterVertex, kMax> raster;
  std::array<uint8_t, kMax> codes;
  std::array<uint32_t, kMax> stamp{};  ///< == current: projected for this cluster
  uint32_t current = 0;

  void NextCluster() {
    if (++current == 0) {
      stamp.fill(0);
      current = 1;
    }
  }
};

// The per-frame inputs of SetUpCluster.
struct SetUpContext {
  const Scene& scene;
  const ClusterFrame& frame;
  const SphereTest& spheres;
  const VertexProjector& projector;
  ClusterVertices& local;
};

// One cluster's triangles, each that may cover a sample handed to
// emit(a, b, c, faceNumber, triangle) (a clipped one as its fan); groups whose
// sphere holds no sample are skipped (testGroups). allFront: the cone showed
// every face front-facing. Returns the triangles counted as drawn.
template <typename Emit>
int SetUpCluster(const SetUpContext& in, const SceneCluster& cluster, bool allFront,
                 bool testGroups, Emit&& emit) {
  const Scene& scene = in.scene;
  ClusterVertices& local = in.local;
  local.NextCluster();
  const SceneTriangle* const triangles = scene.triangles.data();
  const FacePlane* const planes = scene.facePlanesWorld.data();
  const uint32_t* const order = scene.clusters.triangles.data();
  const std::array<uint8_t, 3>* const corners = scene.clusters.corners.data();
  const Vec3* const positions = scene.clusters.positions.data() + cluster.vertexFirst;
  const ClusterGroup* const groups = scene.clusters.groups.data();
  RasterVertex* const raster = local.raster.data();
  uint8_t* const codes = local.codes.data();
  auto project = [&](uint8_t k) {
    if (local.stamp[k] == local.current) return;
    local.stamp[k] = local.current;
    in.projector.Project(positions[k], raster[k], codes[k]);
  };
  const int width = in.spheres.width, height = in.spheres.height;
  int drawn = 0;
  uint32_t lastFace = UINT32_MAX;
  bool front = true;
  constexpr uint32_t kGroup = SceneClusters::kGroupTriangles;
  for (uint32_t first = cluster.first; first < cluster.end; first += kGroup) {
    if (testGroups && !in.spheres.GroupMayCover(groups[first / kGroup])) continue;
    for (uint32_t i = first; i < std::min(first + kGroup, cluster.end); ++i) {
      const uint32_t t = order[i];
      if (!allFront) {
        const uint32_t face = triangles[t].face;
        if (face != lastFace) {
          lastFace = face;
          front = planes[face].FacesPoint(in.frame.eyeWorld);
        }
        if (!front) continue;
      }
      const auto& v = corners[i];
      project(v[0]);
      project(v[1]);
      project(v[2]);
      if ((codes[v[0]] | codes[v[1]] | codes[v[2]]) != 0) {
        if ((codes[v[0]] & codes[v[1]] & codes[v[2]]) != 0) continue;
        std::array<RasterVertex, 10> polygon{};
        const size_t count = ClipToRaster(scene, in.frame, t, polygon);
        if (count < 3) continue;
        const uint32_t faceNumber = triangles[t].face + 1;
        for (size_t j = 1; j + 1 < count; ++j) {
          emit(polygon[0], polygon[j], polygon[j + 1], faceNumber, t);
        }
        ++drawn;
        continue;
      }
      const RasterVertex& a = raster[v[0]];
      const RasterVertex& b = raster[v[1]];
      const RasterVertex& c = raster[v[2]];
      if (!MayCoverSample(a, b, c, width, height)) continue;
      emit(a, b, c, triangles[t].face + 1, t);
      ++drawn;
    }
  }
  return drawn;
}

// Draw order decides a sample only where a later triangle overwrites
// (kOverwrite, kCoverOnly); spatial clusters then go back to scene order.
bool NeedsSceneOrder(const Scene& scene, const ClusterFrame& frame) {
  return !scene.clusters.sceneOrder && frame.rule != DepthRule::kNearestWins;
}

// Scene order; a clipped triangle's fan keeps its own order.
void SortBySceneOrder(std::vector<ClusterStage::Binned>& binned) {
  std::stable_sort(binned.begin(), binned.end(),
                   [](const auto& x, const auto& y) { return x.triangle < y.triangle; });
}

}  // namespace

bool ClusterStage::Usable(const Scene& scene) {
  const auto& clusters = scene.clusters.clusters;
  if (scene.triangles.empty()) return clusters.empty();
  return !clusters.empty() && scene.clusters.triangles.size() == scene.triangles.size() &&
         clusters.front().first == 0 && clusters.back().end == scene.triangles.size();
}

int ClusterStage::Draw(const Scene& scene, const ClusterFrame& frame, int threads,
                       DepthBuffer& depth, CellBuffer& cells) {
  if (threads > 1 && !frame.scanline && scene.triangles.size() >= frame.threadsFromTriangles) {
    return DrawThreaded(scene, frame, threads, depth, cells);
  }
  const SphereTest spheres(frame, cells.WidthCells(), cells.HeightCells());
  const VertexProjector projector(frame.eyeFromWorld, frame.projection, frame.clipPlanes,
                                  frame.floatGeometry);
  ClusterVertices local;
  const SetUpContext context{scene, frame, spheres, projector, local};
  int drawn = 0;
  auto rasterize = [&](const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                       uint32_t faceNumber, uint32_t) {
    if (frame.scanline) {
      RasterizeTriangleScanline(a, b, c, faceNumber, frame.rule, depth, cells);
    } else {
      RasterizeTriangle(a, b, c, faceNumber, frame.rule, depth, cells, frame.depthEncoding);
    }
  };
  const bool ordered = NeedsSceneOrder(scene, frame);
  if (ordered_.empty()) ordered_.resize(1);
  std::vector<Binned>& held = ordered_.front();
  held.clear();
  auto hold = [&](const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                  uint32_t faceNumber, uint32_t triangle) {
    held.push_back({a, b, c, faceNumber, triangle});
  };
  clustersSetUp_ = 0;
  const auto& clusters = scene.clusters.clusters;
  for (size_t k = 0; k < clusters.size(); ++k) {
    const SceneCluster& cluster = clusters[k];
    bool allFront = false, testGroups = false;
    if (!ClusterMayShow(cluster, frame, spheres, allFront, testGroups)) continue;
    ++clustersSetUp_;
    drawn += ordered ? SetUpCluster(context, cluster, allFront, testGroups, hold)
                     : SetUpCluster(context, cluster, allFront, testGroups, rasterize);
  }
  if (ordered) {
    SortBySceneOrder(held);
    for (const Binned& t : held) rasterize(t.a, t.b, t.c, t.faceNumber, t.triangle);
  }
  return drawn;
}

int ClusterStage::DrawThreaded(const Scene& scene, const ClusterFrame& frame, int threads,
                               DepthBuffer& depth, CellBuffer& cells) {
  if (!pool_ || pool_->Workers() != threads) pool_ = std::make_unique<WorkerPool>(threads);
  const int height = cells.HeightCells();
  const SphereTest spheres(frame, cells.WidthCells(), height);
  const VertexProjector projector(frame.eyeFromWorld, frame.projection, frame.clipPlanes,
                                  frame.floatGeometry);
  const auto& clusters = scene.clusters.clusters;
  // Many more runs than threads: which clusters face the eye is uneven along the scene order.
  const int runs = static_cast<int>(std::min<size_t>(clusters.size(), size_t{16} * threads));
  const int bands = std::min(height, 4 * threads);
  const int rowsPerBand = (height + bands - 1) / bands;
  bins_.resize(static_cast<size_t>(runs) * bands);
  for (auto& bin : bins_) bin.clear();
  drawnPerRun_.assign(runs, 0);
  setUpPerRun_.assign(runs, 0);
  ordered_.resize(bands);

  // Step 1: runs of clusters set up in parallel, triangles binned by row band.
  nextTask_ = 0;
  auto setUp = [&](int) {
    ClusterVertices local;
    const SetUpContext context{scene, frame, spheres, projector, local};
    for (int run = nextTask_++; run < runs; run = nextTask_++) {
      const size_t first = clusters.size() * run / runs, end = clusters.size() * (run + 1) / runs;
      std::vector<Binned>* const runBins = bins_.data() + static_cast<size_t>(run) * bands;
      auto bin = [&](const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                     uint32_t faceNumber, uint32_t triangle) {
        const int32_t minY = std::min(a.y, std::min(b.y, c.y));
        const int32_t maxY = std::max(a.y, std::max(b.y, c.y));
        const int firstRow = std::max(0, (minY + kFixedHalf - 1) >> kSubCellBits);
        const int lastRow = std::min(height - 1, (maxY - kFixedHalf) >> kSubCellBits);
        for (int band = firstRow / rowsPerBand;
             band <= lastRow / rowsPerBand && firstRow <= lastRow; ++band) {
          runBins[band].push_back({a, b, c, faceNumber, triangle});
        }
      };
      int drawn = 0;
      for (size_t k = first; k < end; ++k) {
        bool allFront = false, testGroups = false;
        if (!ClusterMayShow(clusters[k], frame, spheres, allFront, testGroups)) continue;
        ++setUpPerRun_[run];
        drawn += SetUpCluster(context, clusters[k], allFront, testGroups, bin);
      }
      drawnPerRun_[run] = drawn;
    }
  };
  pool_->Run(setUp);

  // Step 2: each band drawn by one thread, the runs in order (back in
  // scene order where the rule needs it).
  const bool ordered = NeedsSceneOrder(scene, frame);
  nextTask_ = 0;
  auto drawBands = [&](int) {
    for (int band = nextTask_++; band < bands; band = nextTask_++) {
      const RowRange rows{band * rowsPerBand, std::min(height, (band + 1) * rowsPerBand)};
      auto draw = [&](const Binned& t) {
        RasterizeTriangle(t.a, t.b, t.c, t.faceNumber, frame.rule, depth, cells,
                          frame.depthEncoding, rows);
      };
      std::vector<Binned>& held = ordered_[band];
      held.clear();
      for (int run = 0; run < runs; ++run) {
        const std::vector<Binned>& bin = bins_[static_cast<size_t>(run) * bands + band];
        if (ordered) {
          held.insert(held.end(), bin.begin(), bin.end());
        } else {
          for (const Binned& t : bin) draw(t);
        }
      }
      SortBySceneOrder(held);
      for (const Binned& t : held) draw(t);
    }
  };
  pool_->Run(drawBands);
  int drawn = 0;
  for (int d : drawnPerRun_) drawn += d;
  clustersSetUp_ = 0;
  for (int s : setUpPerRun_) clustersSetUp_ += s;
  return drawn;
}

}  // namespace termshade
