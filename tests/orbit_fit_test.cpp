// The viewer's framing (Framing::kOrbit, render --fit): every vertex inside
// the window, half a cell from its edges, at every orbit angle; never
// smaller than SPEC's fit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "geometry/FitCamera.h"
#include "geometry/OrbitFit.h"
#include "geometry/ViewingTransform.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

struct Window {
  int widthCells;
  int heightCells;
  double cellAspect;
};

constexpr Window kWindows[] = {
    {80, 24, 2.0}, {40, 30, 2.0}, {160, 48, 1.8}, {30, 60, 2.0}, {12, 10, 1.75}};

// The farthest any vertex projects beyond the margin, in cells (<= 0: inside).
double WorstOverhangCells(const Scene& scene, const Camera& camera, const Window& window) {
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  double worst = -1e300;
  for (const Vec3& pWorld : scene.verticesWorld) {
    const CellPoint pCell = ProjectToCell(camera.projection, TransformPoint(eyeFromWorld, pWorld));
    worst = std::max({worst, 0.5 - pCell.u, pCell.u - (window.widthCells - 0.5), 0.5 - pCell.v,
                      pCell.v - (window.heightCells - 0.5)});
  }
  return worst;
}

TEST(OrbitFit, EveryVertexInsideAtEveryOrbitAngle) {
  for (const std::string name : {"beams", "letter_l", "surface", "wedge", "sphere_cone"}) {
    const Scene scene = test::LoadScene("data/" + name + ".dat");
    const double defaultRho = DefaultView(scene.diagonalModelUnits).rho;
    for (const Window& window : kWindows) {
      for (const double fitRho : {defaultRho, 0.5 * defaultRho, 0.6 * scene.diagonalModelUnits}) {
        for (int i = 0; i <= 24; ++i) {
          for (int j = 0; j <= 12; ++j) {
            const ViewParams view{fitRho, 2.0 * std::numbers::pi * i / 24,
                                  std::numbers::pi * j / 12};
            const Camera camera =
                FitCameraAt(scene, view, fitRho, window.widthCells, window.heightCells,
                            window.cellAspect, Framing::kOrbit);
            ASSERT_LE(WorstOverhangCells(scene, camera, window), 1e-9)
                << name << " " << window.widthCells << "x" << window.heightCells << " theta "
                << view.theta << " phi " << view.phi << " fit at " << fitRho;
          }
        }
      }
    }
  }
}

// A column twice as tall as wide (the four sides of a box, z up).
Scene Column() {
  const double w = 0.5, h = 2.0;
  return PrepareScene(test::QuadMesh({{{{-w, -w, -h}, {w, -w, -h}, {w, -w, h}, {-w, -w, h}}},
                                      {{{w, -w, -h}, {w, w, -h}, {w, w, h}, {w, -w, h}}},
                                      {{{w, w, -h}, {-w, w, -h}, {-w, w, h}, {w, w, h}}},
                                      {{{-w, w, -h}, {-w, -w, -h}, {-w, -w, h}, {-w, w, h}}}}),
                      UpAxis::kPlusZ);
}

TEST(OrbitFit, NeverSmallerThanTheSpecFitAndLargerForTallModels) {
  for (const Scene& scene : {test::LoadScene("data/sphere_cone.dat"), Column()}) {
    for (const Window& window : kWindows) {
      const ViewParams view = DefaultView(scene.diagonalModelUnits);
      const Camera spec = FitCamera(scene, view, window.widthCells, window.heightCells,
                                    window.cellAspect, Framing::kSpec);
      const Camera orbit = FitCamera(scene, view, window.widthCells, window.heightCells,
                                     window.cellAspect, Framing::kOrbit);
      EXPECT_GE(orbit.projection.d, spec.projection.d) << window.widthCells;
    }
  }
  // A pane narrower than tall (in screen units): the width limits the
  // sphere, the cylinder of a model taller than wide lets it grow.
  const Scene column = Column();
  ASSERT_NEAR(column.horizontalRadiusModelUnits, std::sqrt(0.5), 1e-12);
  const ViewParams view = DefaultView(column.diagonalModelUnits);
  const Camera spec = FitCamera(column, view, 30, 60, 2.0, Framing::kSpec);
  const Camera orbit = FitCamera(column, view, 30, 60, 2.0, Framing::kOrbit);
  EXPECT_GT(orbit.projection.d, 2.0 * spec.projection.d);
  EXPECT_LE(WorstOverhangCells(column, orbit, {30, 60, 2.0}), 1e-9);
}

// The tangent against a brute-force search over the disk x^2 + f^2 <= R^2, |x| <= r.
TEST(OrbitFit, HorizontalTangentIsTheWidestPointOfSphereAndCylinder) {
  const double radius = 2.0;
  for (const double rho : {2.4, 3.0, 7.2, 50.0}) {
    const double sphereTangent = radius / std::sqrt(rho * rho - radius * radius);
    EXPECT_DOUBLE_EQ(HorizontalTangent(radius, radius, rho), sphereTangent);
    EXPECT_EQ(HorizontalTangent(radius, 0.0, rho), 0.0);
    for (const double horizontal : {0.1, 0.5, 1.0, 1.5, 1.9}) {
      double widest = 0.0;
      for (int k = 0; k < 200000; ++k) {  // the boundary: the arc, cut at |x| = r
        const double angle = 2.0 * std::numbers::pi * k / 200000;
        const double x = std::min(horizontal, radius * std::cos(angle));
        widest = std::max(widest, x / (rho - radius * std::sin(angle)));
      }
      const double tangent = HorizontalTangent(radius, horizontal, rho);
      EXPECT_GE(tangent, widest * (1.0 - 1e-12)) << rho << " " << horizontal;
      EXPECT_NEAR(tangent, widest, 1e-4 * widest) << rho << " " << horizontal;
      EXPECT_LE(tangent, sphereTangent);
    }
  }
}

}  // namespace
}  // namespace termshade
