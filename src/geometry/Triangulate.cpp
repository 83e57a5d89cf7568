#include "geometry/Triangulate.h"

#include <algorithm>
#include <cmath>

#include "geometry/FaceNormal.h"

namespace termshade {
namespace {

struct Point2 {
  double a = 0.0;
  double b = 0.0;
};

double Orient(Point2 p, Point2 q, Point2 r) {
  return (q.a - p.a) * (r.b - p.b) - (q.b - p.b) * (r.a - p.a);
}

bool SamePoint(Point2 p, Point2 q) {
  return p.a == q.a && p.b == q.b;
}

// True when p lies inside or on triangle (x, y, z), which is counter-clockwise.
bool InsideOrOn(Point2 p, Point2 x, Point2 y, Point2 z) {
  return Orient(x, y, p) >= 0.0 && Orient(y, z, p) >= 0.0 && Orient(z, x, p) >= 0.0;
}

// Projects onto the coordinate plane most nearly parallel to the polygon, with
// the axes ordered so that the polygon is counter-clockwise in 2D.
std::vector<Point2> ProjectToDominantPlane(std::span<const Vec3> corners,
                                           const std::vector<uint32_t>& kept, Vec3 normal) {
  const double ax = std::fabs(normal.x), ay = std::fabs(normal.y), az = std::fabs(normal.z);
  std::vector<Point2> out;
  out.reserve(kept.size());
  for (uint32_t i : kept) {
    const Vec3 p = corners[i];
    if (az >= ax && az >= ay) {
      out.push_back(normal.z > 0 ? Point2{p.x, p.y} : Point2{p.y, p.x});
    } else if (ax >= ay) {
      out.push_back(normal.x > 0 ? Point2{p.y, p.z} : Point2{p.z, p.y});
    } else {
      out.push_back(normal.y > 0 ? Point2{p.z, p.x} : Point2{p.x, p.z});
    }
  }
  return out;
}

std::vector<uint32_t> DropConsecutiveDuplicates(std::span<const Vec3> corners) {
  std::vector<uint32_t> kept;
  kept.reserve(corners.size());
  for (uint32_t i = 0; i < corners.size(); ++i) {
    if (!kept.empty() && corners[kept.back()] == corners[i]) continue;
    kept.push_back(i);
  }
  while (kept.size() > 1 && corners[kept.back()] == corners[kept.front()]) kept.pop_back();
  return kept;
}

// Point-in-triangle tests one polygon may spend: far above any sensible
// face (a 2,000-corner outline needs about 4e6), far below a hang.
constexpr int64_t kPointTestBudget = 50'000'000;

class EarClipper {
 public:
  EarClipper(std::vector<Point2> points, int64_t budget)
      : points_(std::move(points)), budget_(budget) {
    const size_t n = points_.size();
    next_.resize(n);
    prev_.resize(n);
    for (size_t i = 0; i < n; ++i) {
      next_[i] = static_cast<uint32_t>((i + 1) % n);
      prev_[i] = static_cast<uint32_t>((i + n - 1) % n);
    }
    remaining_ = n;
  }

  int64_t BudgetLeft() const { return budget_; }

  // Emits triangles of local (kept-list) indices.
  template <typename Emit>
  void Run(Emit emit, const std::atomic<bool>* cancel) {
    uint32_t start = 0;
    uint32_t ears = 0;
    while (remaining_ > 3) {
      if (++ears % kEarsPerCancelPoll == 0 && cancel != nullptr &&
          cancel->load(std::memory_order_relaxed)) {
        return;
      }
      const uint32_t ear = FindEar(start);
      emit(prev_[ear], ear, next_[ear]);
      start = Unlink(ear);
    }
    emit(prev_[start], start, next_[start]);
  }

 private:
  double Convexity(uint32_t i) const {
    return Orient(points_[prev_[i]], points_[i], points_[next_[i]]);
  }

  bool IsEmpty(uint32_t i) const {
    const uint32_t p = prev_[i], n = next_[i];
    const Point2 x = points_[p], y = points_[i], z = points_[n];
    budget_ -= static_cast<int64_t>(remaining_);
    for (uint32_t j = next_[n]; j != p; j = next_[j]) {
      const Point2 q = points_[j];
      if (SamePoint(q, x) || SamePoint(q, y) || SamePoint(q, z)) continue;
      if (InsideOrOn(q, x, y, z)) return false;
    }
    return true;
  }

  // Step 1: a strictly convex empty ear; step 2: a collinear empty corner;
  // step 3 (not a simple polygon): the most convex corner. Past the work
  // budget (hostile input: thousands of reflex corners would make this
  // cubic), corners are clipped in order, so the time stays bounded.
  uint32_t FindEar(uint32_t start) const {
    if (budget_ <= 0) return start;
    uint32_t i = start;
    for (size_t k = 0; k < remaining_; ++k, i = next_[i]) {
      if (Convexity(i) > 0.0 && IsEmpty(i)) return i;
    }
    for (size_t k = 0; k < remaining_; ++k, i = next_[i]) {
      if (Convexity(i) == 0.0 && IsEmpty(i)) return i;
    }
    uint32_t best = start;
    double bestConvexity = -INFINITY;
    for (size_t k = 0; k < remaining_; ++k, i = next_[i]) {
      const double c = Convexity(i);
      if (c > bestConvexity || std::isnan(bestConvexity)) {
        best = i;
        bestConvexity = c;
      }
    }
    return best;
  }

  uint32_t Unlink(uint32_t i) {
    next_[prev_[i]] = next_[i];
    prev_[next_[i]] = prev_[i];
    --remaining_;
    return prev_[i];
  }

  std::vector<Point2> points_;
  std::vector<uint32_t> next_;
  std::vector<uint32_t> prev_;
  size_t remaining_ = 0;
  mutable int64_t budget_;
};

}  // namespace

int64_t ModelPointTestBudget(size_t cornerCount) {
  constexpr int64_t kPerCorner = 32;
  return kPointTestBudget + kPerCorner * static_cast<int64_t>(cornerCount);
}

void TriangulatePolygon(std::span<const Vec3> corners, std::vector<CornerTriangle>& trianglesOut,
                        int64_t* modelBudget, const std::atomic<bool>* cancel) {
  // A triangle of three distinct consecutive corners: what the ear clipper
  // below gives for it (its one ear, emitted from the last corner), without
  // the allocations.
  if (corners.size() == 3 && corners[0] != corners[1] && corners[1] != corners[2] &&
      corners[2] != corners[0]) {
    if (IsFinite(NewellNormal(corners))) trianglesOut.push_back({2, 0, 1});
    return;
  }
  const std::vector<uint32_t> kept = DropConsecutiveDuplicates(corners);
  if (kept.size() < 3) return;
  Vec3 normal = NewellNormal(kept.size(), [&](size_t i) { return corners[kept[i]]; });
  if (!IsFinite(normal)) return;
  if (normal == Vec3{}) normal = {0, 0, 1};  // all collinear: any plane, triangles are empty
  const int64_t budget =
      modelBudget != nullptr ? std::min(kPointTestBudget, *modelBudget) : kPointTestBudget;
  EarClipper clipper(ProjectToDominantPlane(corners, kept, normal), budget);
  clipper.Run(
      [&](uint32_t a, uint32_t b, uint32_t c) {
        trianglesOut.push_back({kept[a], kept[b], kept[c]});
      },
      cancel);
  if (modelBudget != nullptr) *modelBudget -= budget - std::max<int64_t>(clipper.BudgetLeft(), 0);
}

}  // namespace termshade
