#include "raster/RayCastFrame.h"

#include <algorithm>

namespace termshade {
namespace {

// Snapping moves a corner 1/512 cell at most; the projection's own rounding
// is far below the rest.
constexpr double kSnapCells = 1.0 / 512.0 + 1e-6;

}  // namespace

CastFrame::CastFrame(const Scene& s, const RayBvh& b, const ClusterFrame& f, int w, int h)
    : scene(s), bvh(b), frame(f), width(w), height(h) {
  const auto& m = frame.eyeFromWorld.m;
  for (size_t r = 0; r < 3; ++r) {
    for (size_t k = 0; k < 3; ++k) rows[r][k] = m[r * 4 + k];
  }
  const double eyeWorld[3] = {frame.eyeWorld.x, frame.eyeWorld.y, frame.eyeWorld.z};
  eyeLength = Length(frame.eyeWorld);
  depthSide = 0;
  double farDepth = 0.0, boxReach = 0.0, eyeReach = 0.0;
  for (int k = 0; k < 3; ++k) {
    eye[k] = static_cast<float>(eyeWorld[k]);
    forward[k] = static_cast<float>(-rows[2][k]);
    if (forward[k] >= 0.0F) depthSide |= 1U << k;
    farDepth += std::max(-rows[2][k] * (bvh.low[k] - eyeWorld[k]),
                         -rows[2][k] * (bvh.high[k] - eyeWorld[k]));
    boxReach = std::max({boxReach, std::fabs(double{bvh.low[k]}), std::fabs(double{bvh.high[k]})});
    eyeReach = std::max(eyeReach, std::fabs(eyeWorld[k]));
  }
  // The beam of a sample's 1/512-cell square reaches a radius of
  // kSnapCells * sqrt(1 + a^2) / d per unit of depth; rays are
  // (u - cx) / d across, so their length is at most `reach` per unit depth.
  const Projection& p = frame.projection;
  const double across = std::max(std::fabs(p.cx), std::fabs(w - p.cx)) / p.d;
  const double down = std::max(std::fabs(p.cy), std::fabs(h - p.cy)) * p.cellAspect / p.d;
  const double reach = std::sqrt(1.0 + across * across + down * down);
  const double beam = kSnapCells * std::sqrt(1.0 + p.cellAspect * p.cellAspect) / p.d * farDepth;
  // Float rounding: the eye and the reciprocal direction rounded, the slab
  // difference and product, each within 2^-24 relative: positions off by
  // at most about 4e-7 of these magnitudes. (Without the beam term, the
  // tests' frames differ: the margin is not all rounding slack.)
  const double rounding = 2e-6 * (eyeReach + boxReach + farDepth * reach);
  margin = static_cast<float>(beam + rounding);
  coordinateReach = eyeReach + boxReach;
  depthMargin = static_cast<float>(2.0 * (beam + rounding));
}

Vec3 SampleDirection(const CastFrame& cast, int col, int row) {
  const Projection& p = cast.frame.projection;
  const double across = (col + 0.5 - p.cx) / p.d;
  const double down = -(row + 0.5 - p.cy) * p.cellAspect / p.d;
  double d[3];
  for (int k = 0; k < 3; ++k) {
    d[k] = cast.rows[0][k] * across + cast.rows[1][k] * down - cast.rows[2][k];
  }
  return {d[0], d[1], d[2]};
}

Ray MakeRay(const CastFrame& cast, int col, int row) {
  const Vec3 sampleDirection = SampleDirection(cast, col, row);
  const double directions[3] = {sampleDirection.x, sampleDirection.y, sampleDirection.z};
  Ray ray{};
  for (int k = 0; k < 3; ++k) {
    double direction = directions[k];
    // No infinite reciprocal: a tiny tilt instead, far inside the margin.
    if (std::fabs(direction) < 1e-20) direction = direction < 0.0 ? -1e-20 : 1e-20;
    const auto inverse = static_cast<float>(1.0 / direction);
    const bool positive = direction >= 0.0;
    ray.direction[k] = static_cast<float>(direction);
    ray.inverse[k] = Splat(inverse);
    const float shift = positive ? cast.margin : -cast.margin;
    ray.nearFrom[k] = Splat(cast.eye[k] + shift);
    ray.farFrom[k] = Splat(cast.eye[k] - shift);
    if (positive) ray.nearIsLow |= 1U << k;
  }
  return ray;
}

}  // namespace termshade
