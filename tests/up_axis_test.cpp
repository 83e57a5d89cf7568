// The up axis (SPEC 1, 10): an exact signed axis permutation taking the
// file's up axis to +z, applied once when the scene is prepared.
#include <gtest/gtest.h>

#include <charconv>
#include <nlohmann/json.hpp>
#include <numbers>

#include "geometry/Angle.h"
#include "geometry/UpAxis.h"
#include "geometry/ViewingTransform.h"
#include "io/read/DatReader.h"
#include "io/write/FrameFormats.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

constexpr UpAxis kAllAxes[] = {UpAxis::kPlusX,  UpAxis::kMinusX, UpAxis::kPlusY,
                               UpAxis::kMinusY, UpAxis::kPlusZ,  UpAxis::kMinusZ};

Vec3 UnitAlong(UpAxis axis) {
  switch (axis) {
    case UpAxis::kPlusX:
      return {1, 0, 0};
    case UpAxis::kMinusX:
      return {-1, 0, 0};
    case UpAxis::kPlusY:
      return {0, 1, 0};
    case UpAxis::kMinusY:
      return {0, -1, 0};
    case UpAxis::kPlusZ:
      return {0, 0, 1};
    case UpAxis::kMinusZ:
      return {0, 0, -1};
  }
  return {};
}

double Determinant3(const Mat4& m) {
  return m.At(0, 0) * (m.At(1, 1) * m.At(2, 2) - m.At(1, 2) * m.At(2, 1)) -
         m.At(0, 1) * (m.At(1, 0) * m.At(2, 2) - m.At(1, 2) * m.At(2, 0)) +
         m.At(0, 2) * (m.At(1, 0) * m.At(2, 1) - m.At(1, 1) * m.At(2, 0));
}

TEST(UpAxis, NamesParseBack) {
  for (UpAxis axis : kAllAxes) EXPECT_EQ(ParseUpAxis(UpAxisName(axis)), axis);
  EXPECT_EQ(ParseUpAxis("x"), UpAxis::kPlusX);
  EXPECT_EQ(ParseUpAxis("y"), UpAxis::kPlusY);
  EXPECT_EQ(ParseUpAxis("-z"), UpAxis::kMinusZ);
  for (const char* bad : {"", "w", "xy", "+-x", "--y", "z ", "1"}) {
    EXPECT_FALSE(ParseUpAxis(bad).has_value()) << bad;
  }
}

TEST(UpAxis, CycleVisitsEveryAxisOnce) {
  const UpAxis expected[] = {UpAxis::kPlusY,  UpAxis::kPlusX,  UpAxis::kMinusZ,
                             UpAxis::kMinusY, UpAxis::kMinusX, UpAxis::kPlusZ};
  UpAxis axis = UpAxis::kPlusZ;
  for (UpAxis next : expected) {
    axis = NextUpAxis(axis);
    EXPECT_EQ(axis, next);
  }
}

TEST(UpAxis, TurnIsAProperSignedPermutationTakingTheAxisUp) {
  for (UpAxis axis : kAllAxes) {
    const Mat4 m = ZUpFromFile(axis);
    for (int row = 0; row < 3; ++row) {
      int nonZero = 0;
      for (int col = 0; col < 3; ++col) {
        const double e = m.At(row, col);
        EXPECT_TRUE(e == 0.0 || e == 1.0 || e == -1.0);
        nonZero += e != 0.0 ? 1 : 0;
      }
      EXPECT_EQ(nonZero, 1);
      EXPECT_EQ(m.At(row, 3), 0.0);
    }
    EXPECT_EQ(Determinant3(m), 1.0) << UpAxisName(axis);
    EXPECT_EQ(TransformDirection(m, UnitAlong(axis)), (Vec3{0, 0, 1})) << UpAxisName(axis);
    const Vec3 p{0.1, -2.75e-7, 3e12};
    EXPECT_EQ(ZUpFromFile(axis, p), TransformPoint(m, p));
  }
  EXPECT_EQ(ZUpFromFile(UpAxis::kPlusY, Vec3{1, 2, 3}), (Vec3{1, -3, 2}));
}

// A y-up model's file coordinates (x, y, z) written as a z-up .dat with (x, -z, y).
std::string TurnedDat(const Mesh& mesh) {
  std::string out;
  auto append = [&out](double value) {
    char buffer[64];
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
  };
  for (size_t i = 0; i < mesh.verticesFile.size(); ++i) {
    const Vec3 p = mesh.verticesFile[i];
    out += std::to_string(i + 1) + ' ';
    append(p.x);
    out += ' ';
    append(-p.z);
    out += ' ';
    append(p.y);
    out += '\n';
  }
  out += "Faces:\n";
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    for (uint32_t v : mesh.Face(f)) out += std::to_string(v + 1) + ' ';
    out += ".\n";
  }
  return out;
}

TEST(UpAxis, YUpObjRendersAsTheZUpDatItCameFrom) {
  Mesh obj = test::LoadMesh("tests/models/real/spider_y_up.obj");
  ASSERT_GT(obj.FaceCount(), 1000U);
  ASSERT_EQ(obj.upAxisFile, UpAxis::kPlusY);  // OBJ's convention (SPEC 10), from the loader
  Loaded<Mesh> dat = ParseDat(TurnedDat(obj), "spider_z_up.dat");
  ASSERT_TRUE(dat.Ok()) << dat.Error().ToString();
  ASSERT_EQ(dat.Value().upAxisFile, UpAxis::kPlusZ);
  const Scene fromObj = PrepareScene(obj);
  const Scene fromDat = PrepareScene(std::move(dat.Value()));
  EXPECT_EQ(fromObj.upAxis, UpAxis::kPlusY);
  for (Method method : {Method::kZBuffer, Method::kPainter, Method::kWire}) {
    RenderOptions options;
    options.method = method;
    constexpr double kViews[][2] = {{0.3, 1.3}, {2.0, 0.4}, {-1.0, 2.5}};
    for (const auto& [theta, phi] : kViews) {
      EXPECT_EQ(test::RenderFrame(fromObj, theta, phi, 90, 30, options).Text(),
                test::RenderFrame(fromDat, theta, phi, 90, 30, options).Text())
          << MethodName(method) << " " << theta << " " << phi;
    }
  }
}

TEST(UpAxis, OverrideBeatsTheFilesAxisAndWorldFromFileIncludesTheTurn) {
  const Mesh mesh = test::LoadMesh("tests/models/real/spider_z_up_binary.stl");
  for (UpAxis axis : kAllAxes) {
    const Scene scene = PrepareScene(mesh, axis);
    EXPECT_EQ(scene.upAxis, axis);
    EXPECT_TRUE(scene.upAxisOverridden);
    for (size_t v = 0; v < mesh.verticesFile.size(); ++v) {
      const Vec3 expected = TransformPoint(scene.worldFromFile, mesh.verticesFile[v]);
      EXPECT_EQ(scene.verticesWorld[v], expected);
      // World up is the file's up component, shifted: theta orbits about it.
      EXPECT_NEAR(scene.verticesWorld[v].z - scene.worldFromFile.At(2, 3),
                  Dot(UnitAlong(axis), mesh.verticesFile[v]), 1e-12);
    }
  }
  const Scene own = PrepareScene(mesh);
  EXPECT_EQ(own.upAxis, mesh.upAxisFile);
  EXPECT_FALSE(own.upAxisOverridden);
}

TEST(UpAxis, JsonEyeFromFileMapsFileCoordinatesOfATurnedModel) {
  Mesh mesh = test::LoadMesh("tests/models/real/spider_y_up.obj");
  const Scene scene = PrepareScene(std::move(mesh), UpAxis::kPlusY);
  const RenderOptions options;
  const test::Frame frame = test::RenderFrame(scene, 0.7, 1.1, 60, 20, options);
  std::string text;
  AppendJsonFrame(frame.cells, frame.depth, scene, frame.camera, options, text);
  const auto m = nlohmann::json::parse(text)["camera"]["eyeFromFile"];
  const Mat4 eyeFromWorld = EyeFromWorld(frame.camera.view);
  for (size_t v = 0; v < scene.verticesWorld.size(); v += 7) {
    const Vec3 p = scene.VertexFile(v);
    const Vec3 expected = TransformPoint(eyeFromWorld, scene.verticesWorld[v]);
    const double actual[3] = {
        double(m[0]) * p.x + double(m[1]) * p.y + double(m[2]) * p.z + double(m[3]),
        double(m[4]) * p.x + double(m[5]) * p.y + double(m[6]) * p.z + double(m[7]),
        double(m[8]) * p.x + double(m[9]) * p.y + double(m[10]) * p.z + double(m[11])};
    EXPECT_NEAR(actual[0], expected.x, 1e-9);
    EXPECT_NEAR(actual[1], expected.y, 1e-9);
    EXPECT_NEAR(actual[2], expected.z, 1e-9);
  }
}

TEST(Angle, RadiansOrDegrees) {
  EXPECT_EQ(ParseAngleRadians("0.3"), 0.3);
  EXPECT_EQ(ParseAngleRadians("0.3rad"), 0.3);
  EXPECT_EQ(ParseAngleRadians("+2"), 2.0);
  EXPECT_EQ(ParseAngleRadians("-1.5"), -1.5);
  EXPECT_DOUBLE_EQ(*ParseAngleRadians("30deg"), std::numbers::pi / 6.0);
  EXPECT_DOUBLE_EQ(*ParseAngleRadians("-90deg"), -std::numbers::pi / 2.0);
  EXPECT_DOUBLE_EQ(*ParseAngleRadians("1e1deg"), std::numbers::pi / 18.0);
  for (const char* bad :
       {"", "deg", "30 deg", "30dg", "30degs", "inf", "nan", "1e999", "+-1", "0x10", "30°", " 1"}) {
    EXPECT_FALSE(ParseAngleRadians(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace termshade
