#include "geometry/Mat4.h"

namespace termshade {

Mat4 Mat4::Identity() {
  Mat4 r;
  for (int i = 0; i < 4; ++i) r.At(i, i) = 1.0;
  return r;
}

Mat4 Mat4::Translation(Vec3 offset) {
  Mat4 r = Identity();
  r.At(0, 3) = offset.x;
  r.At(1, 3) = offset.y;
  r.At(2, 3) = offset.z;
  return r;
}

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += a.At(i, k) * b.At(k, j);
      r.At(i, j) = sum;
    }
  }
  return r;
}

Vec3 TransformPoint(const Mat4& aFromB, Vec3 pB) {
  const Mat4& t = aFromB;
  return {t.At(0, 0) * pB.x + t.At(0, 1) * pB.y + t.At(0, 2) * pB.z + t.At(0, 3),
          t.At(1, 0) * pB.x + t.At(1, 1) * pB.y + t.At(1, 2) * pB.z + t.At(1, 3),
          t.At(2, 0) * pB.x + t.At(2, 1) * pB.y + t.At(2, 2) * pB.z + t.At(2, 3)};
}

Vec3 TransformDirection(const Mat4& aFromB, Vec3 dirB) {
  const Mat4& t = aFromB;
  return {t.At(0, 0) * dirB.x + t.At(0, 1) * dirB.y + t.At(0, 2) * dirB.z,
          t.At(1, 0) * dirB.x + t.At(1, 1) * dirB.y + t.At(1, 2) * dirB.z,
          t.At(2, 0) * dirB.x + t.At(2, 1) * dirB.y + t.At(2, 2) * dirB.z};
}

}  // namespace termshade
