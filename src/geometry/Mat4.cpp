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

}  // namespace termshade
