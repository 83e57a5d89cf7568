#pragma once

#include <array>

#include "geometry/Vec3.h"

namespace termshade {

/// Row-major 4x4 matrix acting on column vectors (x, y, z, 1).
struct Mat4 {
  std::array<double, 16> m{};

  double& At(int row, int col) { return m[static_cast<size_t>(row * 4 + col)]; }
  double At(int row, int col) const { return m[static_cast<size_t>(row * 4 + col)]; }

  static Mat4 Identity();
  static Mat4 Translation(Vec3 offset);
};

Mat4 operator*(const Mat4& a, const Mat4& b);

/// Applies the affine part to a point (w = 1).
Vec3 TransformPoint(const Mat4& aFromB, Vec3 pB);
/// Applies the linear part only (w = 0): directions and normals of rigid transforms.
Vec3 TransformDirection(const Mat4& aFromB, Vec3 dirB);

}  // namespace termshade
