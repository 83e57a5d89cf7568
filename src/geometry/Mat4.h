#pragma once

#include <array>

#include "geometry/Vec3.h"

namespace termshade {

/// Row-major 4x4 matrix acting on column vectors (x, y, z, 1).
struct Mat4 {
  std::array<double, 16> m{};

  double& At(int row, int col) {
    return m[static_cast<size_t>(row) * 4 + static_cast<size_t>(col)];
  }
  double At(int row, int col) const {
    return m[static_cast<size_t>(row) * 4 + static_cast<size_t>(col)];
  }

  static Mat4 Identity();
  static Mat4 Translation(Vec3 offset);
};

Mat4 operator*(const Mat4& a, const Mat4& b);

/// Applies the affine part to a point (w = 1).
inline Vec3 TransformPoint(const Mat4& aFromB, Vec3 pB) {
  const auto& m = aFromB.m;
  return {m[0] * pB.x + m[1] * pB.y + m[2] * pB.z + m[3],
          m[4] * pB.x + m[5] * pB.y + m[6] * pB.z + m[7],
          m[8] * pB.x + m[9] * pB.y + m[10] * pB.z + m[11]};
}

/// Applies the linear part only (w = 0): directions and normals of rigid transforms.
inline Vec3 TransformDirection(const Mat4& aFromB, Vec3 dirB) {
  const auto& m = aFromB.m;
  return {m[0] * dirB.x + m[1] * dirB.y + m[2] * dirB.z,
          m[4] * dirB.x + m[5] * dirB.y + m[6] * dirB.z,
          m[8] * dirB.x + m[9] * dirB.y + m[10] * dirB.z};
}

}  // namespace termshade
