#include "geometry/ViewingTransform.h"

#include <cmath>

namespace termshade {

Mat4 EyeFromWorld(const ViewParams& view) {
  const double sinTheta = std::sin(view.theta), cosTheta = std::cos(view.theta);
  const double sinPhi = std::sin(view.phi), cosPhi = std::cos(view.phi);
  Mat4 r;
  r.At(0, 0) = -sinTheta;
  r.At(0, 1) = cosTheta;
  r.At(1, 0) = -cosPhi * cosTheta;
  r.At(1, 1) = -cosPhi * sinTheta;
  r.At(1, 2) = sinPhi;
  r.At(2, 0) = sinPhi * cosTheta;
  r.At(2, 1) = sinPhi * sinTheta;
  r.At(2, 2) = cosPhi;
  r.At(2, 3) = -view.rho;
  r.At(3, 3) = 1.0;
  return r;
}

Vec3 EyePositionWorld(const ViewParams& view) {
  const double sinPhi = std::sin(view.phi);
  return {view.rho * sinPhi * std::cos(view.theta), view.rho * sinPhi * std::sin(view.theta),
          view.rho * std::cos(view.phi)};
}

}  // namespace termshade
