#include "geometry/TriangleBvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "geometry/LoadThreads.h"
#include "geometry/Scene.h"

namespace termshade {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The float at or below (above) x.
float FloatDown(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -kInfinity) : f;
}
float FloatUp(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, kInfinity) : f;
}

// The low 10 bits of x spread to every third bit (Morton order).
uint32_t Spread10(uint32_t x) {
  x &= 0x3FFU;
  x = (x | (x << 16)) & 0x030000FFU;
  x = (x | (x << 8)) & 0x0300F00FU;
  x = (x | (x << 4)) & 0x030C30C3U;
  x = (x | (x << 2)) & 0x09249249U;
  return x;
}

// Nodes of the subtree over n leaves (halved by count), memoized: each level
// has at most two sizes.
class SubtreeSizes {
 public:
  uint32_t Nodes(uint32_t n) {
    if (n <= 1) return 1;
    const auto known = nodes_.find(n);
    if (known != nodes_.end()) return known->second;
    const uint32_t total = 1 + Nodes(n / 2) + Nodes(n - n / 2);
    nodes_[n] = total;
    return total;
  }

 private:
  std::map<uint32_t, uint32_t> nodes_;
};

void SetCone(BvhNode& node, float coneCos, double heightMin, double heightMax) {
  node.coneCos = coneCos;
  node.heightMin = FloatDown(heightMin);
  node.heightMax = FloatUp(heightMax);
}

// Float axes about `normal` (the third; any when it is zero), and the
// oriented box about the points' box center that holds them all in those
// axes as stored: coordinates by the inverse of the axes' matrix (double),
// widened past its rounding.
template <typename Points>
void FitOrientedBox(Vec3 normal, const Points& points, BvhNode& node) {
  Vec3 low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  double scale = 0.0;
  points([&](Vec3 p) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    scale = std::max({scale, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  });
  const Vec3 mid = (low + high) * 0.5;
  for (int k = 0; k < 3; ++k)
    node.center[k] = static_cast<float>(k == 0 ? mid.x : k == 1 ? mid.y : mid.z);
  const Vec3 n = Length(normal) > 0.0 ? normal * (1.0 / Length(normal)) : Vec3{0, 0, 1};
  const Vec3 away = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z)
                        ? Vec3{1, 0, 0}
                    : std::fabs(n.y) <= std::fabs(n.z) ? Vec3{0, 1, 0}
                                                       : Vec3{0, 0, 1};
  const Vec3 t1 = Normalized(Cross(n, away));
  const Vec3 axes[3] = {t1, Cross(n, t1), n};
  for (int k = 0; k < 3; ++k) {
    node.axes[k][0] = static_cast<float>(axes[k].x);
    node.axes[k][1] = static_cast<float>(axes[k].y);
    node.axes[k][2] = static_cast<float>(axes[k].z);
  }
  // The stored axes' matrix (columns) and its inverse by cofactors.
  const Vec3 a = node.Axis(0), b = node.Axis(1), c = node.Axis(2);
  const Vec3 bc = Cross(b, c), ca = Cross(c, a), ab = Cross(a, b);
  const double det = Dot(a, bc);
  const Vec3 center = node.Center();
  double half[3] = {0.0, 0.0, 0.0};
  points([&](Vec3 p) {
    const Vec3 d = p - center;
    half[0] = std::max(half[0], std::fabs(Dot(bc, d) / det));
    half[1] = std::max(half[1], std::fabs(Dot(ca, d) / det));
    half[2] = std::max(half[2], std::fabs(Dot(ab, d) / det));
  });
  for (int k = 0; k < 3; ++k) node.half[k] = FloatUp(half[k] * (1.0 + 1e-9) + 1e-12 * scale);
}

// The cone's unit axis as stored (float), normalized again in double.
Vec3 StoredAxis(const BvhNode& node) {
  const Vec3 a = node.Axis(2);
  return a * (1.0 / Length(a));
}

// A leaf: the run of triangles [first, end) in scene order, its box and the
// cone of its faces (zero normals never face a point: left out of the cone).
BvhNode MakeLeaf(const Scene& scene, uint32_t first, uint32_t end) {
  BvhNode node{};
  node.first = first;
  node.count = end - first;
  Vec3 sum{};
  bool any = false, anyDegenerate = false;
  for (uint32_t t = first; t < end; ++t) {
    const Vec3 n = scene.facePlanesWorld[scene.TriangleFace(t)].normal;
    if (Dot(n, n) == 0.0) {
      anyDegenerate = true;
      continue;
    }
    sum = sum + n;
    any = true;
  }
  const bool usable = any && Length(sum) > 1e-6;
  FitOrientedBox(
      usable ? sum : Vec3{},
      [&](auto&& visit) {
        for (uint32_t t = first; t < end; ++t) {
          for (const uint32_t v : scene.triangles[t].vertices) visit(scene.verticesWorld[v]);
        }
      },
      node);
  if (!any) {
    SetCone(node, BvhNode::kAllDegenerate, 0.0, 0.0);
    return node;
  }
  if (!usable) {
    SetCone(node, -1.0F, 0.0, 0.0);
    return node;
  }
  const Vec3 axis = StoredAxis(node);
  const Vec3 center = node.Center();
  double coneCos = 1.0, heightMax = -INFINITY, heightMin = INFINITY;
  for (uint32_t t = first; t < end; ++t) {
    const FacePlane& plane = scene.facePlanesWorld[scene.TriangleFace(t)];
    if (Dot(plane.normal, plane.normal) == 0.0) continue;
    coneCos = std::min(coneCos, Dot(plane.normal, axis));
    const double height = Dot(plane.normal, center) - plane.offset;
    const double slack = 1e-9 * (Length(center) + std::fabs(plane.offset));
    heightMax = std::max(heightMax, height + slack);
    heightMin = std::min(heightMin, height - slack);
  }
  // A degenerate face is never front-facing: never "every face toward" then.
  SetCone(node, FloatDown(coneCos - 1e-6), anyDegenerate ? -INFINITY : heightMin, heightMax);
  return node;
}

// The parent's box (about the children's corners) and cone from its
// children's: the cone widened to hold both (angles added), heights moved to
// the new center (|n| = 1).
void Merge(const BvhNode& left, const BvhNode& right, BvhNode& node) {
  const bool leftAway = left.coneCos == BvhNode::kAllDegenerate;
  const bool rightAway = right.coneCos == BvhNode::kAllDegenerate;
  const bool leftCone = left.coneCos > 0.0F && !leftAway;
  const bool rightCone = right.coneCos > 0.0F && !rightAway;
  // Step 1: the cone's axis, if it can have one.
  Vec3 axis{};
  double angle = 0.0;
  bool usable = false;
  if ((leftCone || leftAway) && (rightCone || rightAway) && !(leftAway && rightAway)) {
    const Vec3 sum =
        (leftCone ? StoredAxis(left) : Vec3{}) + (rightCone ? StoredAxis(right) : Vec3{});
    usable = Length(sum) > 1e-6;
    axis = sum;
  }
  // Step 2: the box about the children's corners.
  FitOrientedBox(
      usable ? axis : Vec3{},
      [&](auto&& visit) {
        for (const BvhNode* child : {&left, &right}) {
          const Vec3 c = child->Center();
          for (int corner = 0; corner < 8; ++corner) {
            Vec3 p = c;
            for (int k = 0; k < 3; ++k) {
              const double sign = (corner >> k & 1) != 0 ? 1.0 : -1.0;
              p = p + child->Axis(k) * (sign * child->half[k]);
            }
            visit(p);
          }
        }
      },
      node);
  // Corners computed in double: widen by their rounding.
  for (int k = 0; k < 3; ++k) {
    node.half[k] = FloatUp(node.half[k] * (1.0 + 1e-9) + 1e-9 * (left.Radius() + right.Radius()));
  }
  // Step 3: the cone.
  if (leftAway && rightAway) return SetCone(node, BvhNode::kAllDegenerate, 0.0, 0.0);
  if (!usable) return SetCone(node, -1.0F, 0.0, 0.0);
  const Vec3 stored = StoredAxis(node);
  const Vec3 center = node.Center();
  double widest = 0.0, heightMin = INFINITY, heightMax = -INFINITY;
  for (const BvhNode* child : {&left, &right}) {
    if (child->coneCos == BvhNode::kAllDegenerate) {
      heightMin = -INFINITY;  // its degenerate faces are never front-facing
      continue;
    }
    widest = std::max(widest, std::acos(std::clamp(Dot(stored, StoredAxis(*child)), -1.0, 1.0)) +
                                  std::acos(std::min(1.0, double{child->coneCos})));
    const double shift = Length(center - child->Center()) * (1.0 + 1e-12) + 1e-9 * Length(center);
    heightMax = std::max(heightMax, child->heightMax + shift);
    heightMin = std::min(heightMin, child->heightMin - shift);
  }
  angle = widest + 1e-6;
  if (!(angle < 1.5)) return SetCone(node, -1.0F, 0.0, 0.0);
  SetCone(node, FloatDown(std::cos(angle) - 1e-6), heightMin, heightMax);
}

// The tree over leaves[order[begin, end)] at nodes[at], depth-first.
class Builder {
 public:
  Builder(const std::vector<BvhNode>& leaves, const std::vector<uint32_t>& order,
          std::vector<BvhNode>& nodes, SubtreeSizes& sizes)
      : leaves_(leaves), order_(order), nodes_(nodes), sizes_(sizes) {}

  void Build(uint32_t begin, uint32_t end, uint32_t at, int depth = 64) const {
    if (end - begin == 1) {
      nodes_[at] = leaves_[order_[begin]];
      return;
    }
    if (depth == 0) return;  // built by another call
    const uint32_t middle = begin + (end - begin) / 2;
    const uint32_t right = at + 1 + sizes_.Nodes(middle - begin);
    Build(begin, middle, at + 1, depth - 1);
    Build(middle, end, right, depth - 1);
    Merge(nodes_[at + 1], nodes_[right], nodes_[at]);
    nodes_[at].first = right;
    nodes_[at].count = 0;
  }

 private:
  const std::vector<BvhNode>& leaves_;
  const std::vector<uint32_t>& order_;
  std::vector<BvhNode>& nodes_;
  SubtreeSizes& sizes_;
};

// The subtrees `depth` levels down: roots and leaf ranges, left to right.
struct Subtree {
  uint32_t begin, end, at;
};
void SplitTop(uint32_t begin, uint32_t end, uint32_t at, int depth, SubtreeSizes& sizes,
              std::vector<Subtree>& out) {
  if (depth == 0 || end - begin == 1) {
    out.push_back({begin, end, at});
    return;
  }
  const uint32_t middle = begin + (end - begin) / 2;
  SplitTop(begin, middle, at + 1, depth - 1, sizes, out);
  SplitTop(middle, end, at + 1 + sizes.Nodes(middle - begin), depth - 1, sizes, out);
}

// The leaves sorted by the Morton code of their box centers (ties by index).
std::vector<uint32_t> MortonOrder(const std::vector<BvhNode>& leaves) {
  Vec3 low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  for (const BvhNode& leaf : leaves) {
    const Vec3 c = leaf.Center();
    low = {std::min(low.x, c.x), std::min(low.y, c.y), std::min(low.z, c.z)};
    high = {std::max(high.x, c.x), std::max(high.y, c.y), std::max(high.z, c.z)};
  }
  const Vec3 extent = high - low;
  const double scale = 1023.0 / std::max({extent.x, extent.y, extent.z, 1e-300});
  std::vector<uint64_t> keys(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) {
    const Vec3 c = (leaves[i].Center() - low) * scale;
    auto cell = [](double x) { return static_cast<uint32_t>(std::clamp(x, 0.0, 1023.0)); };
    const uint32_t code = Spread10(cell(c.x)) | Spread10(cell(c.y)) << 1 | Spread10(cell(c.z)) << 2;
    keys[i] = uint64_t{code} << 32 | i;
  }
  std::sort(keys.begin(), keys.end());
  std::vector<uint32_t> order(leaves.size());
  for (size_t i = 0; i < keys.size(); ++i) order[i] = static_cast<uint32_t>(keys[i]);
  return order;
}

}  // namespace

bool TriangleBvh::BuiltFor(const Scene& scene) const {
  return !nodes.empty() && trianglesData == scene.triangles.data() &&
         triangleCount == scene.triangles.size() && verticesData == scene.verticesWorld.data() &&
         vertexCount == scene.verticesWorld.size();
}

TriangleBvh BuildTriangleBvh(const Scene& scene, const std::atomic<bool>* cancel) {
  TriangleBvh bvh;
  const auto count = static_cast<uint32_t>(scene.triangles.size());
  auto cancelled = [cancel] {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
  };
  if (count == 0 || cancelled()) return bvh;
  // Step 1: the leaves, runs of triangles in scene order (memory order for the frame).
  constexpr uint32_t kRun = TriangleBvh::kLeafTriangles;
  std::vector<BvhNode> leaves((count + kRun - 1) / kRun);
  RunRangesOnLoadThreads(LoadThreadCount(count), leaves.size(), [&](int, size_t begin, size_t end) {
    for (size_t i = begin; i < end && !cancelled(); ++i) {
      const auto first = static_cast<uint32_t>(i * kRun);
      leaves[i] = MakeLeaf(scene, first, std::min(count, first + kRun));
    }
  });
  if (cancelled()) return bvh;
  // Step 2: the tree over the leaves in Morton order, halved by count; the
  // top levels' subtrees built in parallel, then the levels above them.
  const std::vector<uint32_t> order = MortonOrder(leaves);
  const auto leafCount = static_cast<uint32_t>(leaves.size());
  SubtreeSizes sizes;
  bvh.nodes.resize(sizes.Nodes(leafCount));  // memoizes every subtree's size: threads only read
  constexpr int kTopLevels = 3;
  std::vector<Subtree> subtrees;
  SplitTop(0, leafCount, 0, kTopLevels, sizes, subtrees);
  const Builder builder(leaves, order, bvh.nodes, sizes);
  const int threads = std::min(LoadThreadCount(count), static_cast<int>(subtrees.size()));
  RunOnLoadThreads(threads, [&](int part) {
    for (size_t i = static_cast<size_t>(part); i < subtrees.size();
         i += static_cast<size_t>(threads)) {
      builder.Build(subtrees[i].begin, subtrees[i].end, subtrees[i].at);
    }
  });
  builder.Build(0, leafCount, 0, kTopLevels);
  if (cancelled()) return {};
  bvh.trianglesData = scene.triangles.data();
  bvh.triangleCount = count;
  bvh.verticesData = scene.verticesWorld.data();
  bvh.vertexCount = scene.verticesWorld.size();
  return bvh;
}

ClusterFacing NodeFacing(const BvhNode& node, Vec3 eyeWorld) {
  if (node.coneCos == BvhNode::kAllDegenerate) return ClusterFacing::kAway;
  if (!(node.coneCos > 0.0F)) return ClusterFacing::kMixed;
  // As FacingOf (Clusters.cpp): n . (e - c) over the cone, plus the heights.
  const Vec3 center = node.Center();
  const Vec3 v = eyeWorld - center;
  const double length = Length(v);
  // The unit axis coneCos was measured against; |axis x v| does not cancel
  // when the eye lies near the axis, as sqrt(|v|^2 - along^2) would.
  const Vec3 axis = StoredAxis(node);
  const double coneCos = node.coneCos;
  const double along = Dot(axis, v);
  const double across = Length(Cross(axis, v));
  const double sinT = std::sqrt(std::max(0.0, 1.0 - coneCos * coneCos));
  // Margin: rounding of these bounds and of FacesPoint.
  const double margin = 1e-6 * (length + node.Radius() + std::fabs(node.heightMax) +
                                (std::isfinite(node.heightMin) ? std::fabs(node.heightMin) : 0.0)) +
                        1e-9 * (Length(eyeWorld) + Length(center));
  const double most = along * coneCos + across * sinT;
  if (along < length * coneCos && most + node.heightMax < -margin) return ClusterFacing::kAway;
  const double least = along * coneCos - across * sinT;
  if (least > 0.0 && least + node.heightMin > margin) return ClusterFacing::kToward;
  return ClusterFacing::kMixed;
}

}  // namespace termshade
