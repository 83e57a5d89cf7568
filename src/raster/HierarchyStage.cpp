#include "raster/HierarchyStage.h"

#include <algorithm>
#include <cmath>

#include "geometry/FixedRange.h"
#include "raster/FixedPoint.h"
#include "raster/VertexStage.h"

namespace termshade {
namespace {

// A node's box in eye space: its center, and its axes times their half extents.
struct EyeBox {
  double center[3];
  double axes[3][3];  ///< [axis][eye coordinate]
};

// The per-frame constants of the walk.
struct Walk {
  const Scene& scene;
  const TriangleBvh& bvh;
  const ClusterFrame& frame;
  int width, height;

  EyeBox InEye(const BvhNode& node) const {
    const auto& m = frame.eyeFromWorld.m;
    const Vec3 center = node.Center();
    EyeBox box{};
    for (size_t r = 0; r < 3; ++r) {
      const Vec3 row{m[r * 4], m[r * 4 + 1], m[r * 4 + 2]};
      box.center[r] = row.x * center.x + row.y * center.y + row.z * center.z + m[r * 4 + 3];
      for (int k = 0; k < 3; ++k) box.axes[k][r] = Dot(row, node.Axis(k)) * node.half[k];
    }
    return box;
  }

  // False when no triangle of the node can cover a sample: its oriented box,
  // bounded by an eye-space box, projects (0.01 cell margin: more than the
  // snapping's 1/512) onto no cell-center sample.
  bool MayCover(const BvhNode& node) const {
    const EyeBox box = InEye(node);
    const auto& m = frame.eyeFromWorld.m;
    double e[3];
    for (size_t r = 0; r < 3; ++r) {
      e[r] = (std::fabs(box.axes[0][r]) + std::fabs(box.axes[1][r]) + std::fabs(box.axes[2][r])) *
                 (1.0 + 1e-9) +
             1e-9 * (std::fabs(box.center[r]) + std::fabs(m[r * 4 + 3]));
    }
    const double* const c = box.center;
    const double depthNear = -c[2] - e[2], depthFar = -c[2] + e[2];
    if (!(depthNear > 0.0)) return true;  // the eye box reaches the eye: look inside
    // Reciprocals widened past their rounding (and the products' below).
    const double nearScale = (1.0 + 1e-12) / depthNear, farScale = (1.0 - 1e-12) / depthFar;
    auto range = [&](int axis, double& low, double& high) {
      const double lo = c[axis] - e[axis], hi = c[axis] + e[axis];
      high = hi * (hi > 0.0 ? nearScale : farScale);
      low = lo * (lo < 0.0 ? nearScale : farScale);
    };
    double xLow = 0, xHigh = 0, yLow = 0, yHigh = 0;
    range(0, xLow, xHigh);
    range(1, yLow, yHigh);
    const Projection& proj = frame.projection;
    const double vScale = proj.d / proj.cellAspect;
    constexpr double kScreenMargin = 0.01;
    return RangeHoldsSample(proj.cx + proj.d * xLow - kScreenMargin,
                            proj.cx + proj.d * xHigh + kScreenMargin, width) &&
           RangeHoldsSample(proj.cy - vScale * yHigh - kScreenMargin,
                            proj.cy - vScale * yLow + kScreenMargin, height);
  }

  // MayCover, tighter and dearer: the box's eight corners projected one by
  // one (a box wholly in front projects into the hull of its corners).
  bool MayCoverByCorners(const BvhNode& node) const {
    const EyeBox box = InEye(node);
    const double* const c = box.center;
    const auto& a = box.axes;
    const Projection& proj = frame.projection;
    const double vScale = proj.d / proj.cellAspect;
    double uLow = INFINITY, uHigh = -INFINITY, vLow = INFINITY, vHigh = -INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
      double p[3];
      for (int r = 0; r < 3; ++r) {
        p[r] = c[r] + ((corner & 1) != 0 ? a[0][r] : -a[0][r]) +
               ((corner & 2) != 0 ? a[1][r] : -a[1][r]) + ((corner & 4) != 0 ? a[2][r] : -a[2][r]);
      }
      if (!(-p[2] > 0.0)) return true;  // the box reaches the eye: look inside
      const double inverse = 1.0 / -p[2];
      const double u = proj.d * p[0] * inverse, v = -vScale * p[1] * inverse;
      uLow = std::min(uLow, u);
      uHigh = std::max(uHigh, u);
      vLow = std::min(vLow, v);
      vHigh = std::max(vHigh, v);
    }
    // 0.01 cell: the snapping's 1/512 and this arithmetic's rounding (within the guard band).
    constexpr double kScreenMargin = 0.01;
    return RangeHoldsSample(proj.cx + uLow - kScreenMargin, proj.cx + uHigh + kScreenMargin,
                            width) &&
           RangeHoldsSample(proj.cy + vLow - kScreenMargin, proj.cy + vHigh + kScreenMargin,
                            height);
  }

  // A leaf's front-facing triangles (from scene triangle `first`) whose
  // snapped box holds a sample, each corner projected once (a leaf's
  // triangles share most of their corners).
  void DrawLeaf(uint32_t first, bool allFront, std::vector<HierarchyStage::Drawn>& out) const {
    constexpr uint32_t kCorners = 3 * TriangleBvh::kLeafTriangles;
    // NOLINTBEGIN(cppcoreguidelines-pro-type-member-init): filled as corners are met
    uint32_t known[kCorners];
    RasterVertex projected[kCorners];
    // NOLINTEND(cppcoreguidelines-pro-type-member-init)
    uint32_t knownCount = 0;
    auto corner = [&](uint32_t v) -> const RasterVertex& {
      for (uint32_t k = 0; k < knownCount; ++k) {
        if (known[k] == v) return projected[k];
      }
      known[knownCount] = v;
      projected[knownCount] =
          ProjectDirect(frame.eyeFromWorld, frame.projection, scene.verticesWorld[v]);
      return projected[knownCount++];
    };
    const FacePlane* const planes = scene.facePlanesWorld.data();
    const uint32_t end = LeafEnd(first);
    for (uint32_t t = first; t < end; ++t) {
      const uint32_t face = scene.TriangleFace(t);
      if (!allFront && !planes[face].FacesPoint(frame.eyeWorld)) continue;
      const auto& v = scene.triangles[t].vertices;
      const HierarchyStage::Drawn drawn{t, face + 1, {corner(v[0]), corner(v[1]), corner(v[2])}};
      if (MayCoverSample(drawn.corners[0], drawn.corners[1], drawn.corners[2], width, height)) {
        out.push_back(drawn);
      }
    }
  }

  uint32_t LeafEnd(uint32_t first) const {
    return std::min(static_cast<uint32_t>(scene.triangles.size()),
                    first + TriangleBvh::kLeafTriangles);
  }

  // Warms the caches for a leaf drawn soon: its triangles' corners and faces' planes.
  void PrefetchCorners(uint32_t first, bool allFront) const {
    for (uint32_t t = first; t < LeafEnd(first); ++t) {
      for (const uint32_t v : scene.triangles[t].vertices) {
        __builtin_prefetch(&scene.verticesWorld[v]);
      }
      if (!allFront) __builtin_prefetch(&scene.facePlanesWorld[scene.TriangleFace(t)]);
    }
  }

  // The leaves (first triangles) in order, their triangles' lines requested
  // well ahead (a leaf's triangles, then, once those are in, its corners): the
  // leaves lie all over memory, and waiting for each line in turn would cost
  // most of the frame.
  void DrawLeaves(const std::vector<uint32_t>& leaves,
                  std::vector<HierarchyStage::Drawn>& out) const {
    constexpr size_t kTrianglesAhead = 16, kCornersAhead = 8;
    const size_t count = leaves.size();
    for (size_t i = 0; i < count; ++i) {
      if (i + kTrianglesAhead < count) {
        const uint32_t first = leaves[i + kTrianglesAhead] & ~kAllFront;
        __builtin_prefetch(&scene.triangles[first]);
        __builtin_prefetch(&scene.triangles[LeafEnd(first) - 1]);
      }
      if (i + kCornersAhead < count) {
        const uint32_t entry = leaves[i + kCornersAhead];
        PrefetchCorners(entry & ~kAllFront, (entry & kAllFront) != 0);
      }
      DrawLeaf(leaves[i] & ~kAllFront, (leaves[i] & kAllFront) != 0, out);
    }
  }

  /// On a node or leaf entry (indices below 2^31): the cone showed every face front.
  static constexpr uint32_t kAllFront = 1U << 31;

  // The leaves of the subtree at entry `root` (a node index, kAllFront when
  // known) that may hold a front-facing triangle covering a sample, appended
  // to `leaves` (depth-first) as their first triangles, each with kAllFront
  // when known. Inner nodes `split` levels down go to `tasks` instead.
  void Collect(uint32_t root, int split, std::vector<uint32_t>& leaves,
               std::vector<uint32_t>* tasks) const {
    uint32_t stack[64];
    uint8_t levels[64];
    int top = 0;
    stack[top] = root;
    levels[top++] = 0;
    while (top > 0) {
      --top;
      const uint32_t entry = stack[top];
      const int level = levels[top];
      const uint32_t at = entry & ~kAllFront;
      const BvhNode& node = bvh.nodes[at];
      uint32_t allFront = entry & kAllFront;
      if (allFront == 0) {
        const ClusterFacing facing = NodeFacing(node, frame.eyeWorld);
        if (facing == ClusterFacing::kAway) continue;
        if (facing == ClusterFacing::kToward) allFront = kAllFront;
      }
      if (node.count == 0 ? !MayCover(node) : !MayCoverByCorners(node)) continue;
      if (node.count != 0) {
        leaves.push_back(node.first | allFront);
      } else if (tasks != nullptr && level == split) {
        tasks->push_back(at | allFront);
      } else {
        stack[top] = node.first | allFront;  // right child
        levels[top++] = static_cast<uint8_t>(level + 1);
        stack[top] = (at + 1) | allFront;  // left child, first
        levels[top++] = static_cast<uint8_t>(level + 1);
      }
    }
  }
};

}  // namespace

bool HierarchyStage::Applies(const Scene& scene, const TriangleBvh& bvh,
                             const ClusterFrame& frame) {
  if (bvh.Empty() || !frame.cullBackFaces || !frame.clusterCulling || frame.floatGeometry ||
      frame.scanline || frame.sink != nullptr ||
      frame.depthEncoding.format != DepthFormat::kFloatInverseZ) {
    return false;
  }
  if (scene.triangles.size() >= size_t{1} << 31) return false;  // entries keep a flag in bit 31
  // Every corner within the root box's sphere takes the direct path
  // (VertexStage.cpp): twice the near distance in front, half the guard band across.
  const BvhNode& root = bvh.nodes[0];
  const Vec3 c = TransformPoint(frame.eyeFromWorld, root.Center());
  const double r = root.CornerRadius();
  const double margin = 1e-9 * (Length(c) + r);
  const double nearZ = 2.0 * -frame.clipPlanes[0].offset;
  const double depthNear = -c.z - r;
  if (!(depthNear > nearZ * (1.0 + 1e-9) + margin)) return false;
  auto reach = [&](double center) {
    return std::max(std::fabs(center - r), std::fabs(center + r)) / depthNear;
  };
  const Projection& proj = frame.projection;
  const double xLimit = 0.5 * (kClipRangeCells - proj.cx) * (1.0 - 1e-9);
  const double yLimit = 0.5 * (kClipRangeCells - proj.cy) * (1.0 - 1e-9);
  return reach(c.x) * proj.d < xLimit && reach(c.y) * (proj.d / proj.cellAspect) < yLimit;
}

bool HierarchyStage::WouldWalk(const Scene& scene, int widthCells, int heightCells,
                               const RenderOptions& options, double fromTrianglesPerSample) {
  const Method method = options.method;
  const RenderVariant& variant = options.variant;
  if ((method != Method::kZBuffer && method != Method::kCull && method != Method::kAuto) ||
      !options.cullBackFaces || !variant.clusters || !variant.clusterCulling ||
      variant.floatGeometry || variant.scanline ||
      variant.depthFormat != DepthFormat::kFloatInverseZ ||
      variant.hierarchy == HierarchyUse::kNever) {
    return false;
  }
  const SampleGrid grid = FrameSampleGrid(options);
  // Several samples a cell on one thread go to the sampled rasterizer, which does not walk.
  if (grid.Count() > 1 && ResolvedThreadCount(options.threads) <= 1) return false;
  return TrianglesPerSample(scene, widthCells * grid.across, heightCells * grid.down) >=
         fromTrianglesPerSample;
}

int HierarchyStage::Draw(const Scene& scene, const TriangleBvh& bvh, const ClusterFrame& frame,
                         int threads, DepthBuffer& depth, CellBuffer& cells) {
  const Walk walk{scene, bvh, frame, cells.WidthCells(), cells.HeightCells()};
  threads = std::max(1, threads);
  if (perWorker_.size() != static_cast<size_t>(threads)) perWorker_.assign(threads, {});
  // Step 1: the top levels on this thread: the leaves met there, and the
  // subtrees below that may show something, as tasks.
  constexpr int kSplitLevels = 7;  // up to 128 tasks: enough to even out the workers
  tasks_.clear();
  for (Found& found : perWorker_) {
    found.leaves.clear();
    found.drawn.clear();
  }
  walk.Collect(0, threads > 1 ? kSplitLevels : 64, perWorker_[0].leaves, &tasks_);
  // Step 2: each worker takes tasks in turn: their leaves, then the
  // triangles there that may cover a sample.
  nextTask_.store(0);
  auto find = [&](int worker) {
    Found& found = perWorker_[static_cast<size_t>(worker)];
    for (size_t task = nextTask_.fetch_add(1); task < tasks_.size();
         task = nextTask_.fetch_add(1)) {
      walk.Collect(tasks_[task], 0, found.leaves, nullptr);
    }
    walk.DrawLeaves(found.leaves, found.drawn);
  };
  // Step 3: the triangles in scene order (the rule may be that the latest
  // wins), rasterized by row bands, one a worker: every sample sees them in
  // that order whatever the thread count.
  auto rasterize = [&](int worker) {
    const int height = cells.HeightCells();
    const RowRange rows{height * worker / threads, height * (worker + 1) / threads};
    for (const Drawn& d : drawn_) {
      RasterizeTriangle(d.corners[0], d.corners[1], d.corners[2], d.faceNumber, frame.rule, depth,
                        cells, frame.depthEncoding, rows);
    }
  };
  auto merge = [&] {
    drawn_.clear();
    for (const Found& found : perWorker_)
      drawn_.insert(drawn_.end(), found.drawn.begin(), found.drawn.end());
    if (frame.rule != DepthRule::kNearestWins) {
      std::sort(drawn_.begin(), drawn_.end(),
                [](const Drawn& l, const Drawn& r) { return l.triangle < r.triangle; });
    }
  };
  if (threads == 1) {
    find(0);
    merge();
    rasterize(0);
  } else {
    if (!pool_ || pool_->Workers() != threads) pool_ = std::make_unique<WorkerPool>(threads);
    pool_->Run(find);
    merge();
    pool_->Run(rasterize);
  }
  return static_cast<int>(drawn_.size());
}

}  // namespace termshade
