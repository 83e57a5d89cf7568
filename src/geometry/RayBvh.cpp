#include "geometry/RayBvh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "geometry/Scene.h"
#include "process/HugePages.h"
#include "process/LoadThreads.h"

namespace termshade {
namespace {

// The low 21 bits of x spread to every third bit.
uint64_t Spread3(uint64_t x) {
  x &= 0x1FFFFF;
  x = (x | x << 32) & 0x1F00000000FFFF;
  x = (x | x << 16) & 0x1F0000FF0000FF;
  x = (x | x << 8) & 0x100F00F00F00F00F;
  x = (x | x << 4) & 0x10C30C30C30C30C3;
  x = (x | x << 2) & 0x1249249249249249;
  return x;
}

float Down(double x) {
  auto f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -INFINITY);
  return f;
}

float Up(double x) {
  auto f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, INFINITY);
  return f;
}

struct Box {
  double low[3] = {INFINITY, INFINITY, INFINITY};
  double high[3] = {-INFINITY, -INFINITY, -INFINITY};
  void Add(const Vec3& p) {
    const double c[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], c[k]);
      high[k] = std::max(high[k], c[k]);
    }
  }
  void Add(const Box& b) {
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], b.low[k]);
      high[k] = std::max(high[k], b.high[k]);
    }
  }
};

// A subtree's normal cone while building: a unit axis (the stored float
// axis, normalized again) and a half-angle about it.
struct Cone {
  bool allAway = true;  ///< no face with a normal yet (degenerate faces never face a point)
  bool usable = false;
  Vec3 axis;
  double angle = 0.0;
  Vec3 center;  ///< as stored (float)
  double heightMin = INFINITY;
  double heightMax = -INFINITY;
};

Vec3 StoredVector(const float (&v)[3]) {
  return {v[0], v[1], v[2]};
}

// A cone's axis and center as stored (rounded to float first); usable
// stays false when the axis is too short to point anywhere.
Cone StartCone(Vec3 axisSum, const Box& box, RayBvhCone& stored) {
  Cone cone;
  cone.allAway = false;
  const double sumLength = Length(axisSum);
  const Vec3 unit = sumLength > 1e-6 ? axisSum * (1.0 / sumLength) : Vec3{};
  const float axisF[3] = {static_cast<float>(unit.x), static_cast<float>(unit.y),
                          static_cast<float>(unit.z)};
  for (int k = 0; k < 3; ++k) {
    stored.axis[k] = axisF[k];
    stored.center[k] = static_cast<float>((box.low[k] + box.high[k]) / 2);
  }
  cone.center = StoredVector(stored.center);
  stored.coneCos = RayBvhCone::kNoCone;
  const double axisLength = Length(StoredVector(axisF));
  if (sumLength > 1e-6 && axisLength > 0.5) {
    cone.axis = StoredVector(axisF) * (1.0 / axisLength);
    cone.usable = true;
  }
  return cone;
}

// The cone's half-angle and heights, measured against its stored axis and
// center, stored widened past their rounding (too wide: not usable).
void FinishCone(Cone& cone, double widest, double heightMin, double heightMax, const Box& box,
                RayBvhCone& stored) {
  cone.angle = widest + 1e-6;
  cone.heightMin = heightMin;
  cone.heightMax = heightMax;
  if (!cone.usable || !(cone.angle < 1.5)) {
    cone.usable = false;
    stored.coneCos = RayBvhCone::kNoCone;
    return;
  }
  const double diagonal =
      Length(Vec3{box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2]});
  stored.coneCos = Down(std::cos(cone.angle) - 1e-6);
  const double slack = 1e-6 * diagonal + 1e-9 * Length(cone.center);
  stored.heightMin = Down(heightMin - slack);
  stored.heightMax = Up(heightMax + slack);
}

struct Keyed {
  uint64_t code;
  uint32_t triangle;
};

// Morton codes of the triangles' centroids in the scene's box, sorted (ties
// by triangle index: a stable radix sort of keys made in index order).
std::vector<Keyed> SortedByMorton(const Scene& scene, const Box& sceneBox) {
  const size_t count = scene.triangles.size();
  std::vector<Keyed> keys(count), scratch(count);
  double scale[3];
  for (int k = 0; k < 3; ++k) {
    const double extent = sceneBox.high[k] - sceneBox.low[k];
    scale[k] = extent > 0.0 ? 2097151.0 / extent : 0.0;
  }
  RunRangesOnLoadThreads(LoadThreadCount(count), count, [&](int, size_t begin, size_t end) {
    for (size_t t = begin; t < end; ++t) {
      const auto& v = scene.triangles[t].vertices;
      const Vec3 c =
          (scene.verticesWorld[v[0]] + scene.verticesWorld[v[1]] + scene.verticesWorld[v[2]]) *
          (1.0 / 3.0);
      const double at[3] = {c.x, c.y, c.z};
      uint64_t code = 0;
      for (int k = 0; k < 3; ++k) {
        const double q = std::clamp((at[k] - sceneBox.low[k]) * scale[k], 0.0, 2097151.0);
        code |= Spread3(static_cast<uint64_t>(q)) << k;
      }
      keys[t] = {code, static_cast<uint32_t>(t)};
    }
  });
  // LSD radix sort, 11 bits a pass over the 63 bits.
  constexpr int kBits = 11;
  constexpr size_t kBuckets = size_t{1} << kBits;
  std::vector<size_t> counts(kBuckets);
  for (int shift = 0; shift < 63; shift += kBits) {
    std::fill(counts.begin(), counts.end(), 0);
    for (const Keyed& k : keys) ++counts[k.code >> shift & (kBuckets - 1)];
    size_t sum = 0;
    for (size_t& c : counts) sum += std::exchange(c, sum);
    for (const Keyed& k : keys) scratch[counts[k.code >> shift & (kBuckets - 1)]++] = k;
    keys.swap(scratch);
  }
  return keys;
}

// Up to four parts of a sorted range [begin, end).
struct Parts {
  std::pair<size_t, size_t> range[4];
  int count = 0;
};

class Builder {
 public:
  /// Nodes go to `nodes` (children by their index there), triangle indices
  /// to `triangles` (the sorted positions): builders of disjoint ranges may
  /// run at once, each with its own nodes.
  Builder(const Scene& scene, const std::vector<Keyed>& keys, RayBvhLeafTriangle* triangles,
          std::vector<RayBvhNode>& nodes, const std::atomic<bool>* cancel)
      : scene_(scene), keys_(keys), triangles_(triangles), nodes_(nodes), cancel_(cancel) {}

  struct Built {
    uint32_t ref;
    Box box;
    Cone cone;
  };

  // The subtree over sorted triangles [begin, end): a leaf when few, else a
  // node of up to four children (Morton splits of its largest part), before
  // its descendants in `nodes`.
  Built Build(size_t begin, size_t end) {
    if (end - begin <= RayBvh::kLeafTriangles) return Leaf(begin, end);
    if (cancel_ != nullptr && cancel_->load(std::memory_order_relaxed))
      return {RayBvh::kEmpty, {}, {}};
    const auto node = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    const Parts parts = Split(begin, end);
    Built children[4];
    for (int i = 0; i < parts.count; ++i) {
      children[i] = Build(parts.range[i].first, parts.range[i].second);
    }
    return Finish(node, parts, children);
  }

  // Up to four children: the largest part split again while any part is
  // more than a leaf (fuller nodes make a shallower tree).
  Parts Split(size_t begin, size_t end) const {
    Parts parts;
    parts.range[0] = {begin, end};
    parts.count = 1;
    if (end - begin <= size_t{4} * RayBvh::kLeafTriangles) {
      // Few enough for full leaves: runs of the Morton order, which lie together.
      parts.count = 0;
      for (size_t b = begin; b < end; b += RayBvh::kLeafTriangles) {
        parts.range[parts.count++] = {b, std::min(end, b + RayBvh::kLeafTriangles)};
      }
    }
    auto size = [&](int i) { return parts.range[i].second - parts.range[i].first; };
    while (parts.count < 4) {
      int largest = -1;
      for (int i = 0; i < parts.count; ++i) {
        if (size(i) > RayBvh::kLeafTriangles && (largest < 0 || size(i) > size(largest))) {
          largest = i;
        }
      }
      if (largest < 0) break;
      const auto [b, e] = parts.range[largest];
      const size_t middle = MortonSplit(b, e);
      for (int i = parts.count; i > largest + 1; --i) parts.range[i] = parts.range[i - 1];
      parts.range[largest] = {b, middle};
      parts.range[largest + 1] = {middle, e};
      ++parts.count;
    }
    return parts;
  }

  // Node `node` of `nodes` over its built children: boxes, cone and slabs.
  Built Finish(uint32_t node, const Parts& parts, const Built* children) {
    Box box;
    RayBvhNode filled{};
    Cone cones[4];
    for (int i = 0; i < 4; ++i) {
      Box childBox;
      filled.child[i] = RayBvh::kEmpty;
      if (i < parts.count) {
        filled.child[i] = children[i].ref;
        childBox = children[i].box;
        cones[i] = children[i].cone;
        box.Add(childBox);
      }
      for (int k = 0; k < 3; ++k) {
        // An empty child: low +inf, high -inf, which no ray reaches.
        filled.low[k][i] = i < parts.count ? Down(childBox.low[k]) : INFINITY;
        filled.high[k][i] = i < parts.count ? Up(childBox.high[k]) : -INFINITY;
      }
    }
    Cone cone = MergeCones(cones, parts.count, box, filled.cone);
    SetSlabs(parts.range, parts.count, filled);
    nodes_[node] = filled;
    return {node, box, cone};
  }

 private:
  Built Leaf(size_t begin, size_t end) {
    Box box;
    const auto first = static_cast<uint32_t>(begin);
    Vec3 normalSum{};
    bool anyFacing = false, anyDegenerate = false;
    for (size_t i = begin; i < end; ++i) {
      const uint32_t t = keys_[i].triangle;
      const auto& corners = scene_.triangles[t].vertices;
      triangles_[i] = {{corners[0], corners[1], corners[2]}, t};
      for (const uint32_t v : scene_.triangles[t].vertices) box.Add(scene_.verticesWorld[v]);
      const Vec3 n = scene_.facePlanesWorld[scene_.TriangleFace(t)].normal;
      anyFacing = anyFacing || Dot(n, n) != 0.0;
      anyDegenerate = anyDegenerate || Dot(n, n) == 0.0;
      normalSum = normalSum + n;
    }
    Built built{RayBvh::LeafRef(first, static_cast<uint32_t>(end - begin)), box, {}};
    if (!anyFacing) return built;  // every face degenerate: never facing
    RayBvhCone stored{};
    built.cone = StartCone(normalSum, box, stored);
    if (!built.cone.usable) return built;
    double widest = 0.0, heightMin = INFINITY, heightMax = -INFINITY;
    const Vec3 center = built.cone.center;
    for (size_t i = begin; i < end; ++i) {
      const FacePlane& plane = scene_.facePlanesWorld[scene_.TriangleFace(keys_[i].triangle)];
      if (Dot(plane.normal, plane.normal) == 0.0) continue;
      widest =
          std::max(widest, std::acos(std::clamp(Dot(plane.normal, built.cone.axis), -1.0, 1.0)));
      const double slack = 1e-9 * (Length(center) + std::fabs(plane.offset));
      const double height = Dot(plane.normal, center) - plane.offset;
      heightMin = std::min(heightMin, height - slack);
      heightMax = std::max(heightMax, height + slack);
    }
    // A degenerate face never faces a point: never "every face toward" then.
    FinishCone(built.cone, widest, anyDegenerate ? -INFINITY : heightMin, heightMax, box, stored);
    return built;
  }

  // A node's cone from its children's: axes summed, angles added to their
  // axes' angle from it, heights moved to its center (|n| = 1).
  static Cone MergeCones(const Cone* cones, int count, const Box& box, RayBvhCone& stored) {
    Vec3 axisSum{};
    bool allAway = true, anyUnusable = false, anyDegenerate = false;
    for (int i = 0; i < count; ++i) {
      anyDegenerate = anyDegenerate || cones[i].allAway || cones[i].heightMin == -INFINITY;
      if (cones[i].allAway) continue;
      allAway = false;
      anyUnusable = anyUnusable || !cones[i].usable;
      axisSum = axisSum + cones[i].axis;
    }
    if (allAway) {
      stored.coneCos = RayBvhCone::kAllAway;
      return {};
    }
    Cone cone = StartCone(axisSum, box, stored);
    if (anyUnusable) cone.usable = false;
    double widest = 0.0, heightMin = INFINITY, heightMax = -INFINITY;
    if (cone.usable) {
      for (int i = 0; i < count; ++i) {
        const Cone& child = cones[i];
        if (child.allAway) continue;
        widest = std::max(
            widest, std::acos(std::clamp(Dot(cone.axis, child.axis), -1.0, 1.0)) + child.angle);
        const double shift =
            Length(cone.center - child.center) * (1.0 + 1e-12) + 1e-9 * Length(cone.center);
        heightMin = std::min(heightMin, child.heightMin - shift);
        heightMax = std::max(heightMax, child.heightMax + shift);
      }
    }
    FinishCone(cone, widest, anyDegenerate ? -INFINITY : heightMin, heightMax, box, stored);
    return cone;
  }

  // Each child's slab along the node's stored cone axis (x without a usable
  // cone: no tighter than the box, but a test like the others): its
  // corners' extent along it.
  void SetSlabs(const std::pair<size_t, size_t>* parts, int partCount, RayBvhNode& node) const {
    RayBvhCone& cone = node.cone;
    if (!(cone.coneCos > 0.0F) || cone.coneCos == RayBvhCone::kAllAway) {
      cone.axis[0] = 1.0F;
      cone.axis[1] = cone.axis[2] = 0.0F;
    }
    const Vec3 stored = StoredVector(cone.axis);
    for (int i = 0; i < 4; ++i) {
      double low = INFINITY, high = -INFINITY;
      for (size_t k = i < partCount ? parts[i].first : 0; i < partCount && k < parts[i].second;
           ++k) {
        for (const uint32_t v : scene_.triangles[keys_[k].triangle].vertices) {
          const double along = Dot(stored, scene_.verticesWorld[v]);
          low = std::min(low, along);
          high = std::max(high, along);
        }
      }
      // The products' rounding, about the coordinates' size.
      const double slack = 1e-12 * (std::fabs(low) + std::fabs(high));
      node.slabLow[i] = i < partCount ? Down(low - slack) : INFINITY;
      node.slabHigh[i] = i < partCount ? Up(high + slack) : -INFINITY;
    }
  }

  // Where [begin, end) splits: at the highest bit in which its codes differ
  // (they are sorted, so one binary search), or in half where all are equal.
  size_t MortonSplit(size_t begin, size_t end) const {
    const uint64_t first = keys_[begin].code, last = keys_[end - 1].code;
    if (first == last) return begin + (end - begin) / 2;
    const uint64_t bit = std::bit_floor(first ^ last);
    const auto at = std::partition_point(keys_.begin() + static_cast<std::ptrdiff_t>(begin),
                                         keys_.begin() + static_cast<std::ptrdiff_t>(end),
                                         [bit](const Keyed& k) { return (k.code & bit) == 0; });
    return static_cast<size_t>(at - keys_.begin());
  }

  const Scene& scene_;
  const std::vector<Keyed>& keys_;
  RayBvhLeafTriangle* triangles_;
  std::vector<RayBvhNode>& nodes_;
  const std::atomic<bool>* cancel_;
};

// From this many triangles the root's subtrees are built on two threads.
constexpr size_t kTwoThreadsFrom = 100000;

// The whole tree from a root node, the root's children split between this
// thread and another: this one builds the first parts straight after the
// root, the other the rest into its own nodes, appended after (child
// indices moved): the nodes come out in the one-thread order.
void BuildOnTwoThreads(const Scene& scene, const std::vector<Keyed>& keys,
                       const std::atomic<bool>* cancel, RayBvh& bvh) {
  Builder first(scene, keys, bvh.triangles.data(), bvh.nodes, cancel);
  bvh.nodes.emplace_back();
  const Parts parts = first.Split(0, keys.size());
  // The first parts on this thread, about half the triangles.
  int split = 1;
  while (split + 1 < parts.count && parts.range[split].second <= keys.size() / 2) ++split;
  std::vector<RayBvhNode> rest;
  rest.reserve((keys.size() - parts.range[split].first) / 2 + 1);
  AdviseHugePages(rest);
  Builder second(scene, keys, bvh.triangles.data(), rest, cancel);
  Builder::Built children[4];
  RunOnLoadThreads(2, [&](int thread) {
    for (int i = thread == 0 ? 0 : split; i < (thread == 0 ? split : parts.count); ++i) {
      children[i] =
          (thread == 0 ? first : second).Build(parts.range[i].first, parts.range[i].second);
    }
  });
  const auto offset = static_cast<uint32_t>(bvh.nodes.size());
  auto moved = [offset](uint32_t ref) {
    return ref == RayBvh::kEmpty || RayBvh::IsLeaf(ref) ? ref : ref + offset;
  };
  for (RayBvhNode node : rest) {
    for (uint32_t& child : node.child) child = moved(child);
    bvh.nodes.push_back(node);
  }
  for (int i = split; i < parts.count; ++i) children[i].ref = moved(children[i].ref);
  first.Finish(0, parts, children);
}

}  // namespace

ClusterFacing ConeFacing(const RayBvhCone& cone, Vec3 pWorld, double pLength) {
  if (cone.coneCos == RayBvhCone::kAllAway) return ClusterFacing::kAway;
  if (!(cone.coneCos > 0.0F)) return ClusterFacing::kMixed;
  // As FacingOf (Clusters.cpp): n . p - offset = n . v + (n . c - offset)
  // with v = p - c; over a cone of half-angle t about a, at angle phi from
  // v: max n . v = (a . v) cos t + |a x v| sin t when phi > t, min n . v =
  // (a . v) cos t - |a x v| sin t when phi + t < 90 degrees. The stored
  // axis is unit within 1e-7 and |a x v| is taken from |v|^2 - (a . v)^2:
  // both widened by their error.
  const Vec3 v{pWorld.x - cone.center[0], pWorld.y - cone.center[1], pWorld.z - cone.center[2]};
  const double lengthSquared = Dot(v, v);
  const double length = std::sqrt(lengthSquared);
  const double along = cone.axis[0] * v.x + cone.axis[1] * v.y + cone.axis[2] * v.z;
  const double coneCos = cone.coneCos;
  const double across = std::sqrt(std::max(0.0, lengthSquared - along * along)) + 1e-7 * length;
  const double sinT = std::sqrt(1.0 - coneCos * coneCos);
  const double margin = 1e-6 * (length + std::fabs(double{cone.heightMax}) +
                                (std::isfinite(cone.heightMin) ? std::fabs(cone.heightMin) : 0.0)) +
                        1e-9 * (2.0 * pLength + length);
  if (along < length * coneCos - 1e-6 * length &&
      along * coneCos + across * sinT + cone.heightMax < -margin) {
    return ClusterFacing::kAway;
  }
  const double least = along * coneCos - across * sinT;
  if (least > 1e-6 * length && least + cone.heightMin > margin) return ClusterFacing::kToward;
  return ClusterFacing::kMixed;
}

bool RayBvh::BuiltFor(const Scene& scene) const {
  return !nodes.empty() && trianglesData == scene.triangles.data() &&
         triangleCount == scene.triangles.size() && verticesData == scene.verticesWorld.data() &&
         vertexCount == scene.verticesWorld.size();
}

size_t EstimateRayBvhBytes(const Scene& scene) {
  constexpr size_t kBytesPerTriangle = 72;
  return scene.triangles.size() < RayBvh::kMaxTriangles ? kBytesPerTriangle * scene.triangles.size()
                                                        : 0;
}

RayBvh BuildRayBvh(const Scene& scene, const std::atomic<bool>* cancel, int threads) {
  RayBvh bvh;
  const size_t count = scene.triangles.size();
  if (count == 0 || count >= RayBvh::kMaxTriangles) return bvh;
  if (threads <= 0) threads = LoadThreadCount(count);
  // Step 1: the box of every vertex a triangle uses, and the Morton order.
  Box sceneBox;
  for (const SceneTriangle& t : scene.triangles) {
    for (const uint32_t v : t.vertices) sceneBox.Add(scene.verticesWorld[v]);
  }
  if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) return {};
  std::vector<Keyed> keys = SortedByMorton(scene, sceneBox);
  if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) return {};
  // Step 2: the tree, depth first from a root node (a root that would be a
  // lone leaf becomes a node with one leaf child), the root's subtrees on
  // two threads for big scenes (the same nodes in the same order).
  // Every frame reads both at random: huge pages spare a TLB miss a read.
  bvh.triangles.reserve(count);
  AdviseHugePages(bvh.triangles);
  bvh.triangles.resize(count);
  bvh.nodes.reserve(count / 2 + 1);
  AdviseHugePages(bvh.nodes);
  Builder builder(scene, keys, bvh.triangles.data(), bvh.nodes, cancel);
  if (count <= RayBvh::kLeafTriangles) {
    bvh.nodes.emplace_back();
    const Builder::Built leaf = builder.Build(0, count);
    RayBvhNode& root = bvh.nodes[0];
    root.cone = {{0, 0, 0}, {1, 0, 0}, RayBvhCone::kNoCone, 0.0F, 0.0F};
    for (int i = 0; i < 4; ++i) {
      root.child[i] = i == 0 ? leaf.ref : RayBvh::kEmpty;
      root.slabLow[i] = i == 0 ? -INFINITY : INFINITY;
      root.slabHigh[i] = i == 0 ? INFINITY : -INFINITY;
      for (int k = 0; k < 3; ++k) {
        root.low[k][i] = i == 0 ? Down(leaf.box.low[k]) : INFINITY;
        root.high[k][i] = i == 0 ? Up(leaf.box.high[k]) : -INFINITY;
      }
    }
  } else if (threads >= 2 && count >= kTwoThreadsFrom) {
    BuildOnTwoThreads(scene, keys, cancel, bvh);
  } else {
    builder.Build(0, count);
  }
  if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) return {};
  for (int k = 0; k < 3; ++k) {
    bvh.low[k] = Down(sceneBox.low[k]);
    bvh.high[k] = Up(sceneBox.high[k]);
  }
  bvh.trianglesData = scene.triangles.data();
  bvh.triangleCount = count;
  bvh.verticesData = scene.verticesWorld.data();
  bvh.vertexCount = scene.verticesWorld.size();
  return bvh;
}

}  // namespace termshade
