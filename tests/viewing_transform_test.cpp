// The viewing transform and projection of SPEC 2 and 3, by hand-computed
// values and by their properties.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/FitCamera.h"
#include "geometry/Projection.h"
#include "geometry/ViewingTransform.h"

namespace termshade {
namespace {

TEST(ViewingTransform, MatchesHandComputedMatrix) {
  const Mat4 v = EyeFromWorld({10.0, 0.3, 1.3});
  // Values of SPEC 2's V (transposed: we act on column vectors) at theta 0.3, phi 1.3.
  const double expected[4][4] = {
      {-0.29552020666133955, 0.955336489125606, 0.0, 0.0},
      {-0.25555139178342545, -0.0790513091168043, 0.963558185417193, 0.0},
      {0.9205222939247008, 0.2847509140847142, 0.26749882862458735, -10.0},
      {0.0, 0.0, 0.0, 1.0},
  };
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(v.At(r, c), expected[r][c], 1e-15) << r << "," << c;
  }
  const Vec3 pEye = TransformPoint(v, {1, 2, 3});
  EXPECT_NEAR(pEye.x, 1.6151527715898724, 1e-14);
  EXPECT_NEAR(pEye.y, 2.4770205462345447, 1e-14);
  EXPECT_NEAR(pEye.z, -7.707479392032109, 1e-14);
}

TEST(ViewingTransform, EyeOnXAxisSeesZUpAndYRight) {
  const Mat4 v = EyeFromWorld({5.0, 0.0, std::numbers::pi / 2});
  const Vec3 up = TransformDirection(v, {0, 0, 1});
  const Vec3 right = TransformDirection(v, {0, 1, 0});
  const Vec3 origin = TransformPoint(v, {0, 0, 0});
  EXPECT_NEAR(up.y, 1.0, 1e-15);
  EXPECT_NEAR(right.x, 1.0, 1e-15);
  EXPECT_NEAR(origin.z, -5.0, 1e-15);
  EXPECT_NEAR(origin.x, 0.0, 1e-15);
}

TEST(ViewingTransform, IsRigidAndPutsTheEyeAtTheOrigin) {
  for (double theta : {-2.0, 0.0, 0.3, 1.7, 4.0}) {
    for (double phi : {0.01, 0.7, 1.3, 2.9}) {
      const ViewParams view{7.5, theta, phi};
      const Mat4 v = EyeFromWorld(view);
      // Rows of the rotation are orthonormal.
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
          const double dot =
              v.At(a, 0) * v.At(b, 0) + v.At(a, 1) * v.At(b, 1) + v.At(a, 2) * v.At(b, 2);
          EXPECT_NEAR(dot, a == b ? 1.0 : 0.0, 1e-14);
        }
      }
      // Right-handed: x cross y = z.
      const Vec3 x{v.At(0, 0), v.At(0, 1), v.At(0, 2)}, y{v.At(1, 0), v.At(1, 1), v.At(1, 2)};
      const Vec3 z = Cross(x, y);
      EXPECT_NEAR(z.x, v.At(2, 0), 1e-14);
      EXPECT_NEAR(z.z, v.At(2, 2), 1e-14);
      const Vec3 eyeInEye = TransformPoint(v, EyePositionWorld(view));
      EXPECT_NEAR(Length(eyeInEye), 0.0, 1e-13);
      EXPECT_NEAR(TransformPoint(v, {0, 0, 0}).z, -7.5, 1e-14);
    }
  }
}

TEST(Projection, CentralProjectionAndCellAspect) {
  const Projection proj{20.0, 40.0, 12.0, 2.0};
  // X = -d x / z = 20 * 1 / 4 = 5; Y = 20 * 2 / 4 = 10; u = 40 + 5, v = 12 - 10 / 2.
  const CellPoint p = ProjectToCell(proj, {1.0, 2.0, -4.0});
  EXPECT_DOUBLE_EQ(p.u, 45.0);
  EXPECT_DOUBLE_EQ(p.v, 7.0);
  EXPECT_DOUBLE_EQ(p.w, 0.25);
  // A taller cell shows the same height in fewer rows.
  const CellPoint taller = ProjectToCell({20.0, 40.0, 12.0, 2.5}, {1.0, 2.0, -4.0});
  EXPECT_DOUBLE_EQ(taller.v, 8.0);
}

TEST(Projection, FitKeepsTheBoundingSphereInsideWithMargin) {
  const double radius = 2.0, rho = 7.0;
  for (auto [cols, rows, aspect] : {std::tuple{80, 24, 2.0}, {160, 48, 1.75}, {40, 40, 2.0}}) {
    const Projection proj = FitProjection(radius, rho, cols, rows, aspect);
    const double projectedRadius = proj.d * radius / std::sqrt(rho * rho - radius * radius);
    EXPECT_LE(projectedRadius, 0.5 * cols + 1e-9);
    EXPECT_LE(projectedRadius / aspect, 0.5 * rows + 1e-9);
    EXPECT_NEAR(std::min(0.5 * cols, 0.5 * rows * aspect) * 0.9, projectedRadius, 1e-9);
  }
}

TEST(Projection, OrbitingDoesNotChangeTheFitButDistanceDoes) {
  Scene scene;
  scene.diagonalModelUnits = 4.0;
  scene.radiusModelUnits = 2.0;
  const Camera a = FitCamera(scene, {7.2, 0.3, 1.3}, 80, 24, 2.0);
  const Camera b = FitCamera(scene, {7.2, 2.0, 0.5}, 80, 24, 2.0);
  const Camera far = FitCamera(scene, {14.4, 0.3, 1.3}, 80, 24, 2.0);
  EXPECT_EQ(a.projection.d, b.projection.d);
  EXPECT_EQ(a.projection.d, far.projection.d);  // the same d: twice as far looks half as big
  const Camera refit = FitCameraAt(scene, {7.2, 0.3, 1.3}, 14.4, 80, 24, 2.0);
  EXPECT_GT(refit.projection.d, a.projection.d);  // fitted farther away: larger d
}

TEST(ViewParams, DefaultsFollowTheSpec) {
  const ViewParams view = DefaultView(5.0);
  const ViewLimits limits = LimitsForDiagonal(5.0);
  EXPECT_DOUBLE_EQ(limits.rhoMin, 3.0);
  EXPECT_DOUBLE_EQ(limits.rhoMax, 3000.0);
  EXPECT_DOUBLE_EQ(view.rho, 9.0);
  EXPECT_DOUBLE_EQ(view.theta, 0.3);
  EXPECT_DOUBLE_EQ(view.phi, 1.3);
}

}  // namespace
}  // namespace termshade
