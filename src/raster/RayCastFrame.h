#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "geometry/RayBvh.h"
#include "geometry/Scene.h"
#include "geometry/Vec3.h"
#include "raster/ClusterStage.h"

// What RayCastStage and its tiles share: the frame's fixed quantities, one
// sample's ray, and the ray's tests of four boxes at once.
namespace termshade {

/// Four lanes of a SIMD register (GCC vector extensions).
using Floats4 = float __attribute__((vector_size(16)));
using Ints4 = int32_t __attribute__((vector_size(16)));

inline Floats4 Load4(const float* p) {
  Floats4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Both ends of a small object: it may straddle two cache lines.
template <typename T>
inline void PrefetchWhole(const T* p) {
  static_assert(sizeof(T) <= 64);
  __builtin_prefetch(p);
  __builtin_prefetch(reinterpret_cast<const char*>(p) + sizeof(T) - 1);
}

inline Floats4 Splat(float x) {
  return Floats4{x, x, x, x};
}

inline Floats4 Min4(Floats4 a, Floats4 b) {
  return a < b ? a : b;
}
inline Floats4 Max4(Floats4 a, Floats4 b) {
  return a > b ? a : b;
}

/// What a frame of RayCastStage fixes for every ray (world space).
struct CastFrame {
  const Scene& scene;
  const RayBvh& bvh;
  const ClusterFrame& frame;
  int width, height;
  double rows[3][3];       ///< eyeFromWorld's rotation rows (world vectors)
  float eye[3];            ///< world
  float forward[3];        ///< world: the view direction (eye -z)
  uint32_t depthSide;      ///< per axis bit: forward >= 0 (the near side of a box is its low)
  float margin;            ///< world units every box is widened by
  float depthMargin;       ///< subtracted from a box's nearest depth
  double eyeLength;        ///< |eye|
  double coordinateReach;  ///< the largest |coordinate| of the eye and the root box

  CastFrame(const Scene& s, const RayBvh& b, const ClusterFrame& f, int w, int h);
};

// One sample's ray: its direction's reciprocals and the widened planes' offsets.
struct Ray {
  float direction[3];
  Floats4 inverse[3];   ///< 1 / direction, per axis, splat
  Floats4 nearFrom[3];  ///< eye -+ margin: where the near planes' distances are taken from
  Floats4 farFrom[3];
  uint32_t nearIsLow;  ///< per axis bit: direction >= 0
};

// The world direction from the eye through a sample's center.
Vec3 SampleDirection(const CastFrame& cast, int col, int row);

/// The sample's ray, its box planes widened by the frame's margin.
Ray MakeRay(const CastFrame& cast, int col, int row);

// Where the ray's widened beam enters and leaves four boxes (SoA, as
// RayBvhNode stores them); an empty box (low +inf, high -inf) is never entered.
struct BoxSpan {
  Floats4 entry, exit;
};

inline BoxSpan BoxSpans(const float* low, const float* high, const Ray& ray) {
  Floats4 entry = Splat(0.0F), exit = Splat(INFINITY);
  for (size_t k = 0; k < 3; ++k) {
    const bool nearLow = (ray.nearIsLow >> k & 1U) != 0;
    const Floats4 nearPlane = Load4((nearLow ? low : high) + 4 * k);
    const Floats4 farPlane = Load4((nearLow ? high : low) + 4 * k);
    entry = Max4(entry, (nearPlane - ray.nearFrom[k]) * ray.inverse[k]);
    exit = Min4(exit, (farPlane - ray.farFrom[k]) * ray.inverse[k]);
  }
  return {entry, exit};
}

// Four boxes' nearest eye depth, less the depth margin: no corner inside is nearer.
inline Floats4 NearestDepths(const CastFrame& cast, const float* low, const float* high) {
  Floats4 depth = Splat(-cast.depthMargin);
  for (size_t k = 0; k < 3; ++k) {
    const bool depthLow = (cast.depthSide >> k & 1U) != 0;
    depth += (Load4((depthLow ? low : high) + 4 * k) - Splat(cast.eye[k])) * Splat(cast.forward[k]);
  }
  return depth;
}

}  // namespace termshade
