#include "raster/RayCastStage.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>

#include "geometry/FixedRange.h"
#include "raster/EdgeFunction.h"
#include "raster/FixedPoint.h"
#include "raster/RayCastFrame.h"
#include "raster/RayTileFrontier.h"
#include "raster/VertexStage.h"

namespace termshade {
namespace {

// Relative slack of a depth bound: float 1/z of a corner, and the
// interpolation's three roundings (SPEC 5: 1/z interpolated in float).
constexpr float kDepthSlack = 1e-5F;
// A tree is at most 91 levels deep (63 Morton bits, then halving up to 2^28
// triangles), three entries a level and four pushed at once, below a tile's
// TileFrontier::kMaxEntries.
constexpr int kStackEntries = 512;

// What a sample has found so far.
struct SampleResult {
  float w = 0.0F;           ///< the depth buffer's cleared value
  uint32_t faceNumber = 0;  ///< background
  int64_t triangle = -1;    ///< cull: the latest in scene order
  int covering = 0;
};

struct StackEntry {
  uint32_t ref;
  float nearestDepth;  ///< no corner below it is nearer (eye depth, world units)
  uint32_t allFront;   ///< a cone above showed every face below it front-facing
};

// One sample's walk in progress. A walk waits on memory at every step (the
// next node or leaf, a leaf's corners), so a worker keeps several
// walks and steps each in turn: what one step asks for is prefetched and
// arrives while the others step.
}  // namespace

struct alignas(64) RayCastStage::Lane {
  enum class Phase : uint8_t { kWalk, kLeafFaces, kLeafTest, kIdle };
  Phase phase = Phase::kIdle;
  int col = 0, row = 0;
  int top = 0;
  uint32_t leaf = 0;
  uint32_t leafAllFront = 0;
  Ray ray{};
  SampleResult result;
  StackEntry stack[kStackEntries] = {};
};

namespace {

using Lane = RayCastStage::Lane;

class SampleCaster {
 public:
  explicit SampleCaster(const CastFrame& cast) : cast_(cast) {}

  // A walk from the tile's entries the sample's beam enters (pushed farthest first).
  void Start(Lane& lane, int col, int row, const std::vector<EntryGroup>& entries) const {
    lane.phase = Lane::Phase::kWalk;
    lane.col = col;
    lane.row = row;
    lane.ray = MakeRay(cast_, col, row);
    lane.result = {};
    lane.top = 0;
    for (const EntryGroup& group : entries) {
      const auto [entry, exit] = BoxSpans(&group.low[0][0], &group.high[0][0], lane.ray);
      const Ints4 bits = (entry <= exit) & Ints4{1, 2, 4, 8};
      for (auto mask = static_cast<unsigned>(bits[0] | bits[1] | bits[2] | bits[3]); mask != 0;
           mask &= mask - 1) {
        const int i = std::countr_zero(mask);
        lane.stack[lane.top++] = {group.ref[i], group.nearestDepth[i], group.allFront[i]};
      }
    }
  }

  // One step of the lane's walk; false once it has its result.
  bool Step(Lane& lane) const {
    switch (lane.phase) {
      case Lane::Phase::kLeafFaces:  // facing will be tested: the face planes
        for (const RayBvhLeafTriangle& record : LeafRecords(lane.leaf)) {
          __builtin_prefetch(
              &cast_.scene.facePlanesWorld[cast_.scene.TriangleFace(record.triangle)]);
        }
        lane.phase = Lane::Phase::kLeafTest;
        return true;
      case Lane::Phase::kLeafTest:
        TestLeaf(lane);
        lane.phase = Lane::Phase::kWalk;
        return true;
      case Lane::Phase::kWalk:
        return Walk(lane);
      case Lane::Phase::kIdle:
        break;
    }
    return false;
  }

 private:
  std::span<const RayBvhLeafTriangle> LeafRecords(uint32_t leaf) const {
    return {cast_.bvh.triangles.data() + RayBvh::LeafFirst(leaf), RayBvh::LeafCount(leaf)};
  }

  // Pops to the next entry worth visiting: a node's children are pushed
  // (their memory requested), a leaf's triangle list requested.
  bool Walk(Lane& lane) const {
    const bool nearest = cast_.frame.rule == DepthRule::kNearestWins;
    const float bestW = nearest ? lane.result.w : 0.0F;
    while (lane.top > 0) {
      const StackEntry entry = lane.stack[--lane.top];
      if (bestW > 0.0F && entry.nearestDepth * bestW > 1.0F + kDepthSlack) continue;
      if (RayBvh::IsLeaf(entry.ref)) {
        // Its records were requested when it was pushed: their corners now
        // (and, when facing is to be tested, their faces).
        lane.leaf = entry.ref;
        lane.leafAllFront = entry.allFront;
        const bool facesNeeded = entry.allFront == 0;
        for (const RayBvhLeafTriangle& record : LeafRecords(entry.ref)) {
          for (const uint32_t v : record.vertices) PrefetchWhole(&cast_.scene.verticesWorld[v]);
          if (facesNeeded && !cast_.scene.triangleFaces.empty()) {
            __builtin_prefetch(&cast_.scene.triangleFaces[record.triangle]);
          }
        }
        lane.phase = facesNeeded ? Lane::Phase::kLeafFaces : Lane::Phase::kLeafTest;
        return true;
      }
      // Subtrees facing away (the far side) are dropped by their cones;
      // below a cone facing the eye no face is tested for facing.
      uint32_t allFront = entry.allFront;
      if (allFront == 0) {
        const ClusterFacing facing =
            ConeFacing(cast_.bvh.nodes[entry.ref].cone, cast_.frame.eyeWorld, cast_.eyeLength);
        if (facing == ClusterFacing::kAway) continue;
        allFront = facing == ClusterFacing::kToward ? 1 : 0;
      }
      lane.top =
          PushChildren(cast_.bvh.nodes[entry.ref], lane.ray, bestW, allFront, lane.stack, lane.top);
      return true;
    }
    lane.phase = Lane::Phase::kIdle;
    return false;
  }

  // The children the ray's widened beam reaches, pushed farthest first,
  // their nodes requested.
  int PushChildren(const RayBvhNode& node, const Ray& ray, float bestW, uint32_t allFront,
                   StackEntry* stack, int top) const {
    const float* const low = &node.low[0][0];
    const float* const high = &node.high[0][0];
    auto [entry, exit] = BoxSpans(low, high, ray);
    const Floats4 depth = NearestDepths(cast_, low, high);
    // The slabs along the node's axis: a . (eye + t d) within each child's, widened.
    const float* const axis = node.cone.axis;
    const float along =
        axis[0] * ray.direction[0] + axis[1] * ray.direction[1] + axis[2] * ray.direction[2];
    const float from = axis[0] * cast_.eye[0] + axis[1] * cast_.eye[1] + axis[2] * cast_.eye[2];
    const float inverseAlong = 1.0F / (std::fabs(along) < 1e-30F ? 1e-30F : along);
    const Floats4 toLow = (Load4(node.slabLow) - Splat(cast_.margin + from)) * Splat(inverseAlong);
    const Floats4 toHigh =
        (Load4(node.slabHigh) + Splat(cast_.margin - from)) * Splat(inverseAlong);
    entry = Max4(entry, Min4(toLow, toHigh));
    exit = Min4(exit, Max4(toLow, toHigh));
    Ints4 keep = entry <= exit;
    if (bestW > 0.0F) keep &= depth * Splat(bestW) <= Splat(1.0F + kDepthSlack);
    const Ints4 bits = keep & Ints4{1, 2, 4, 8};
    unsigned mask = static_cast<unsigned>(bits[0] | bits[1] | bits[2] | bits[3]);
    // Nearest first off the stack: pushed in order of depth, farthest first.
    StackEntry found[4] = {};
    int count = 0;
    for (; mask != 0; mask &= mask - 1) {
      const int i = std::countr_zero(mask);
      int at = count++;
      while (at > 0 && found[at - 1].nearestDepth < depth[i]) {
        found[at] = found[at - 1];
        --at;
      }
      found[at] = {node.child[i], depth[i], allFront};
      if (RayBvh::IsLeaf(node.child[i])) {
        const std::span<const RayBvhLeafTriangle> records = LeafRecords(node.child[i]);
        __builtin_prefetch(records.data());
        __builtin_prefetch(&records.back().triangle);
      } else {
        const auto* const line = reinterpret_cast<const char*>(&cast_.bvh.nodes[node.child[i]]);
        static_assert(sizeof(RayBvhNode) == 192);  // three lines (aligned to one)
        __builtin_prefetch(line);
        __builtin_prefetch(line + 64);
        __builtin_prefetch(line + 128);
      }
    }
    std::memcpy(stack + top, found, sizeof found);  // the stack keeps room for four more
    return top + count;
  }

  // The leaf's triangles, each corner projected once (a leaf's triangles
  // share most of their corners).
  void TestLeaf(Lane& lane) const {
    const Scene& scene = cast_.scene;
    constexpr uint32_t kCorners = 3 * RayBvh::kLeafTriangles;
    uint32_t known[kCorners];
    RasterVertex projected[kCorners];
    uint32_t knownCount = 0;
    auto corner = [&](uint32_t v) -> const RasterVertex& {
      for (uint32_t k = 0; k < knownCount; ++k) {
        if (known[k] == v) return projected[k];
      }
      known[knownCount] = v;
      projected[knownCount] =
          ProjectDirect(cast_.frame.eyeFromWorld, cast_.frame.projection, scene.verticesWorld[v]);
      return projected[knownCount++];
    };
    for (const RayBvhLeafTriangle& record : LeafRecords(lane.leaf)) {
      const auto& v = record.vertices;
      TestTriangle(record.triangle, corner(v[0]), corner(v[1]), corner(v[2]), lane);
    }
  }

  // A triangle decided exactly as the rasterizer decides the sample; facing
  // (the face plane, another line of memory) only when it covers it.
  void TestTriangle(uint32_t t, const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                    Lane& lane) const {
    const Scene& scene = cast_.scene;
    const ClusterFrame& frame = cast_.frame;
    const int col = lane.col, row = lane.row;
    SampleResult& result = lane.result;
    // The rasterizer's steps: oriented clockwise on screen, edge functions
    // with the top-left bias, 1/z from the edge weights (TriangleRasterizer.cpp).
    const auto [v0, v1, v2, area] = OrientClockwise(a, b, c);
    if (area == 0) return;
    const int64_t sampleX = int64_t{col} * kFixedOne + kFixedHalf;
    const int64_t sampleY = int64_t{row} * kFixedOne + kFixedHalf;
    const int64_t e12 = MakeEdgeFunction(*v1, *v2, sampleX, sampleY).atOrigin;
    const int64_t e20 = MakeEdgeFunction(*v2, *v0, sampleX, sampleY).atOrigin;
    const int64_t e01 = MakeEdgeFunction(*v0, *v1, sampleX, sampleY).atOrigin;
    if ((e12 | e20 | e01) < 0) return;
    const uint32_t face = scene.TriangleFace(t);
    if (lane.leafAllFront == 0 && !scene.facePlanesWorld[face].FacesPoint(frame.eyeWorld)) return;
    ++result.covering;
    const uint32_t faceNumber = face + 1;
    if (frame.rule == DepthRule::kCoverOnly || frame.rule == DepthRule::kOverwrite) {
      if (static_cast<int64_t>(t) < result.triangle) return;
      result.triangle = t;
      result.faceNumber = faceNumber;
      if (frame.rule == DepthRule::kCoverOnly) return;
    }
    const float invArea = 1.0F / static_cast<float>(area);
    const float k0 = v0->w * invArea, k1 = v1->w * invArea, k2 = v2->w * invArea;
    const float w =
        static_cast<float>(e12) * k0 + static_cast<float>(e20) * k1 + static_cast<float>(e01) * k2;
    if (frame.rule == DepthRule::kOverwrite) {
      result.w = w;
      return;
    }
    if (w > result.w || (w == result.w && faceNumber < result.faceNumber)) {
      result.w = w;
      result.faceNumber = faceNumber;
    }
  }

  const CastFrame& cast_;
};

}  // namespace

RayCastStage::RayCastStage() = default;
RayCastStage::~RayCastStage() = default;

bool RayCastStage::Applies(const Scene& scene, const RayBvh& bvh, const ClusterFrame& frame) {
  if (bvh.Empty() || !frame.cullBackFaces || !frame.clusterCulling || frame.floatGeometry ||
      frame.scanline || frame.sink != nullptr ||
      frame.depthEncoding.format != DepthFormat::kFloatInverseZ || !bvh.BuiltFor(scene)) {
    return false;
  }
  // Every corner within the root box's sphere takes the direct path
  // (VertexStage.cpp): twice the near distance in front, half the guard band across.
  const Vec3 centerWorld{(double{bvh.low[0]} + bvh.high[0]) / 2,
                         (double{bvh.low[1]} + bvh.high[1]) / 2,
                         (double{bvh.low[2]} + bvh.high[2]) / 2};
  const Vec3 half{(double{bvh.high[0]} - bvh.low[0]) / 2, (double{bvh.high[1]} - bvh.low[1]) / 2,
                  (double{bvh.high[2]} - bvh.low[2]) / 2};
  const Vec3 c = TransformPoint(frame.eyeFromWorld, centerWorld);
  const double r = Length(half) * (1.0 + 1e-9);
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

bool RayCastStage::WouldCast(const Scene& scene, int widthCells, int heightCells,
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
  // Several samples a cell on one thread go to the sampled rasterizer, which casts no rays.
  if (grid.Count() > 1 && ResolvedThreadCount(options.threads) <= 1) return false;
  return TrianglesPerSample(scene, widthCells * grid.across, heightCells * grid.down) >=
         fromTrianglesPerSample;
}

int RayCastStage::Draw(const Scene& scene, const RayBvh& bvh, const ClusterFrame& frame,
                       WorkerPool* pool, DepthBuffer& depth, CellBuffer& cells) {
  const int width = cells.WidthCells(), height = cells.HeightCells();
  const CastFrame cast(scene, bvh, frame, width, height);
  const SampleCaster caster(cast);
  const bool writesDepth = frame.rule != DepthRule::kCoverOnly;
  const int threads = pool != nullptr ? pool->Workers() : 1;
  coveredPerWorker_.assign(static_cast<size_t>(threads), 0);
  if (laneCount_ < static_cast<size_t>(threads) * kLanes) {
    laneCount_ = static_cast<size_t>(threads) * kLanes;
    lanes_ = std::make_unique<Lane[]>(laneCount_);
  }
  if (tileEntriesCount_ < static_cast<size_t>(threads)) {
    tileEntriesCount_ = static_cast<size_t>(threads);
    tileEntries_ = std::make_unique<TileEntries[]>(tileEntriesCount_);
  }
  const int tilesAcross = (width + kTileCols - 1) / kTileCols;
  const int tileCount = tilesAcross * ((height + kTileRows - 1) / kTileRows);
  const TileFrontier frontier(cast);
  nextTile_.store(0);
  auto castTiles = [&](int worker) {
    auto& faces = cells.FaceNumbers();
    Lane* const lanes = lanes_.get() + static_cast<size_t>(worker) * kLanes;
    TileEntries& entries = tileEntries_[static_cast<size_t>(worker)];
    int covered = 0;
    Tile tile{0, 0, 0, 0};
    int col = 0, row = 0;
    // The next sample of this worker's tiles into a lane; false when none is left.
    auto feed = [&](Lane& lane) {
      if (col == tile.col1) {
        col = tile.col0;
        ++row;
      }
      if (row >= tile.row1) {
        const int index = nextTile_.fetch_add(1);
        if (index >= tileCount) return false;
        const int col0 = index % tilesAcross * kTileCols, row0 = index / tilesAcross * kTileRows;
        tile = {col0, row0, std::min(width, col0 + kTileCols), std::min(height, row0 + kTileRows)};
        frontier.Find(tile, entries);
        col = tile.col0;
        row = tile.row0;
      }
      caster.Start(lane, col++, row, entries.groups);
      return true;
    };
    int active = 0;
    for (int i = 0; i < kLanes; ++i) active += feed(lanes[i]) ? 1 : 0;
    while (active > 0) {
      for (int i = 0; i < kLanes; ++i) {
        Lane& lane = lanes[i];
        if (lane.phase == Lane::Phase::kIdle || caster.Step(lane)) continue;
        const SampleResult& result = lane.result;
        if (result.covering != 0) {
          covered += result.covering;
          const size_t index = cells.Index(lane.col, lane.row);
          faces[index] = result.faceNumber;
          if (writesDepth && result.faceNumber != 0) depth.At(index) = result.w;
        }
        if (!feed(lane)) --active;
      }
    }
    coveredPerWorker_[static_cast<size_t>(worker)] = covered;
  };
  if (threads == 1) {
    castTiles(0);
  } else {
    pool->Run(castTiles);
  }
  int covered = 0;
  for (const int c : coveredPerWorker_) covered += c;
  return covered;
}

}  // namespace termshade
