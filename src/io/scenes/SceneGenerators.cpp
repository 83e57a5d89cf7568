#include "io/scenes/SceneGenerators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

namespace termshade {
namespace {

struct Point2 {
  double a = 0.0;
  double b = 0.0;
};

// Maps profile coordinates (a, b) and extrusion depth c to file space; must
// be a proper rotation plus offset so counter-clockwise stays counter-clockwise.
using ExtrusionFrame = std::function<Vec3(double a, double b, double c)>;

uint32_t AddVertex(Mesh& mesh, Vec3 p) {
  mesh.verticesFile.push_back(p);
  return static_cast<uint32_t>(mesh.verticesFile.size() - 1);
}

// A prism: the counter-clockwise profile at c = 0 (facing -c) and c = depth
// (facing +c), joined by one quad per profile edge.
void AddExtrusion(Mesh& mesh, const std::vector<Point2>& profile, double depth,
                  const ExtrusionFrame& frame) {
  const size_t n = profile.size();
  std::vector<uint32_t> low(n), high(n);
  for (size_t i = 0; i < n; ++i) low[i] = AddVertex(mesh, frame(profile[i].a, profile[i].b, 0));
  for (size_t i = 0; i < n; ++i) {
    high[i] = AddVertex(mesh, frame(profile[i].a, profile[i].b, depth));
  }
  mesh.AddFace(std::vector<uint32_t>(low.rbegin(), low.rend()));
  mesh.AddFace(high);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    mesh.AddFace(std::array<uint32_t, 4>{low[i], low[j], high[j], high[i]});
  }
}

ExtrusionFrame AlongZ() {
  return [](double a, double b, double c) { return Vec3{a, b, c}; };
}

Mesh Cube() {
  Mesh mesh;
  AddExtrusion(mesh, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1.0, AlongZ());
  return mesh;
}

// SPEC 6's example, kept verbatim.
Mesh Wedge() {
  Mesh mesh;
  mesh.verticesFile = {{1, 0, 0}, {1, 3, 0}, {0, 3, 0}, {0, 0, 0}, {1, 0, 5}, {0, 0, 5}};
  mesh.AddFace(std::array<uint32_t, 3>{0, 1, 4});
  mesh.AddFace(std::array<uint32_t, 3>{2, 3, 5});
  mesh.AddFace(std::array<uint32_t, 4>{1, 2, 5, 4});
  mesh.AddFace(std::array<uint32_t, 4>{0, 4, 5, 3});
  mesh.AddFace(std::array<uint32_t, 4>{0, 3, 2, 1});
  return mesh;
}

// A solid capital L: a non-convex hexagon extruded by 1.
Mesh LetterL() {
  Mesh mesh;
  AddExtrusion(mesh, {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 5}, {0, 5}}, 1.0, AlongZ());
  return mesh;
}

// Three tilted beams in a pinwheel: each passes over the next one's low end
// and under the previous one's high end, so no back-to-front order exists.
Mesh Beams() {
  Mesh mesh;
  constexpr double kInradius = 1.0, kHalfLength = 3.0, kHalfWidth = 0.6, kThickness = 0.3;
  const double crossing = kInradius * std::sqrt(3.0);  // where neighbouring axes cross
  for (int k = 0; k < 3; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 3.0;
    const Vec3 along{std::cos(angle), std::sin(angle), 0};
    const Vec3 side{-along.y, along.x, 0};
    // Rises along the beam: high (z ~ 1) where it crosses the next beam's low end.
    const double slope = 0.35 / crossing;
    const Vec3 base = side * kInradius;
    auto frame = [=](double a, double b, double c) {
      const double t = c - kHalfLength;
      const Vec3 axis = base + along * t + Vec3{0, 0, 0.5 - slope * t};
      return axis + side * a + Vec3{0, 0, b};
    };
    AddExtrusion(
        mesh,
        {{-kHalfWidth, 0}, {kHalfWidth, 0}, {kHalfWidth, kThickness}, {-kHalfWidth, kThickness}},
        2.0 * kHalfLength, frame);
  }
  return mesh;
}

// Sphere cap and ring faces between latitude rings of `ring(i, j)` indices.
void AddBandedSurface(Mesh& mesh, int rings, int segments,
                      const std::function<uint32_t(int, int)>& ring, uint32_t topPole,
                      std::optional<uint32_t> bottomPole) {
  for (int j = 0; j < segments; ++j) {
    const int next = (j + 1) % segments;
    mesh.AddFace(std::array<uint32_t, 3>{topPole, ring(0, j), ring(0, next)});
    for (int i = 0; i + 1 < rings; ++i) {
      mesh.AddFace(
          std::array<uint32_t, 4>{ring(i, j), ring(i + 1, j), ring(i + 1, next), ring(i, next)});
    }
    if (bottomPole) {
      mesh.AddFace(std::array<uint32_t, 3>{ring(rings - 1, j), *bottomPole, ring(rings - 1, next)});
    }
  }
}

void AddSphere(Mesh& mesh, Vec3 center, double radius, int latitudeBands, int longitudeBands) {
  const uint32_t north = AddVertex(mesh, center + Vec3{0, 0, radius});
  const auto first = static_cast<uint32_t>(mesh.verticesFile.size());
  for (int i = 1; i < latitudeBands; ++i) {
    const double polar = std::numbers::pi * i / latitudeBands;
    for (int j = 0; j < longitudeBands; ++j) {
      const double azimuth = 2.0 * std::numbers::pi * j / longitudeBands;
      AddVertex(mesh, center + Vec3{radius * std::sin(polar) * std::cos(azimuth),
                                    radius * std::sin(polar) * std::sin(azimuth),
                                    radius * std::cos(polar)});
    }
  }
  const uint32_t south = AddVertex(mesh, center - Vec3{0, 0, radius});
  AddBandedSurface(
      mesh, latitudeBands - 1, longitudeBands,
      [&](int i, int j) { return first + static_cast<uint32_t>(i * longitudeBands + j); }, north,
      south);
}

void AddCone(Mesh& mesh, Vec3 baseCenter, double radius, double height, int rings, int segments) {
  const uint32_t apex = AddVertex(mesh, baseCenter + Vec3{0, 0, height});
  const auto first = static_cast<uint32_t>(mesh.verticesFile.size());
  for (int i = 1; i <= rings; ++i) {
    const double s = static_cast<double>(i) / rings;
    for (int j = 0; j < segments; ++j) {
      const double azimuth = 2.0 * std::numbers::pi * j / segments;
      AddVertex(mesh, baseCenter + Vec3{s * radius * std::cos(azimuth),
                                        s * radius * std::sin(azimuth), (1.0 - s) * height});
    }
  }
  auto ring = [&](int i, int j) { return first + static_cast<uint32_t>(i * segments + j); };
  AddBandedSurface(mesh, rings, segments, ring, apex, std::nullopt);
  std::vector<uint32_t> base;  // seen from below: the last ring backwards
  for (int j = segments - 1; j >= 0; --j) base.push_back(ring(rings - 1, j));
  mesh.AddFace(base);
}

Mesh SphereAndCone() {
  Mesh mesh;
  AddSphere(mesh, {-1.25, 0, 0}, 1.0, 30, 50);
  AddCone(mesh, {1.35, 0.2, -1.0}, 0.9, 2.3, 4, 90);
  return mesh;
}

// z = sin(x) cos(y) over [-pi, pi]^2 as planar triangles (the grid's quads
// would not be planar), every one written in both orders: a two-sided sheet.
Mesh FunctionSurface() {
  Mesh mesh;
  constexpr int kCells = 20;
  for (int i = 0; i <= kCells; ++i) {
    for (int j = 0; j <= kCells; ++j) {
      const double x = std::numbers::pi * (2.0 * i / kCells - 1.0);
      const double y = std::numbers::pi * (2.0 * j / kCells - 1.0);
      AddVertex(mesh, {x, y, std::sin(x) * std::cos(y)});
    }
  }
  auto at = [](int i, int j) { return static_cast<uint32_t>(i * (kCells + 1) + j); };
  for (int i = 0; i < kCells; ++i) {
    for (int j = 0; j < kCells; ++j) {
      for (const auto& t : {std::array<uint32_t, 3>{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                            std::array<uint32_t, 3>{at(i, j), at(i + 1, j + 1), at(i, j + 1)}}) {
        mesh.AddFace(t);
        mesh.AddFace(std::array<uint32_t, 3>{t[0], t[2], t[1]});
      }
    }
  }
  return mesh;
}

// Five steps: the staircase profile (non-convex) extruded across the flight.
Mesh Steps() {
  Mesh mesh;
  constexpr int kSteps = 5;
  constexpr double kTread = 1.0, kRise = 0.6, kWidth = 3.0;
  std::vector<Point2> profile{{0, 0}, {kSteps * kTread, 0}, {kSteps * kTread, kSteps * kRise}};
  for (int s = kSteps - 1; s >= 0; --s) {
    profile.push_back({s * kTread, (s + 1) * kRise});
    profile.push_back({s * kTread, s * kRise});
  }
  profile.pop_back();  // (0, 0) is the first corner already
  // Profile (a, b) onto (-x, z), extruded along +y: a proper rotation that
  // puts the bottom step towards +x, where the default eye is.
  AddExtrusion(mesh, profile, kWidth, [](double a, double b, double c) { return Vec3{-a, c, b}; });
  return mesh;
}

}  // namespace

const std::vector<std::string>& GeneratedSceneNames() {
  static const std::vector<std::string> kNames{"cube",        "wedge",   "letter_l", "beams",
                                               "sphere_cone", "surface", "steps"};
  return kNames;
}

std::optional<Mesh> GenerateScene(std::string_view name) {
  std::optional<Mesh> mesh;
  if (name == "cube") mesh = Cube();
  if (name == "wedge") mesh = Wedge();
  if (name == "letter_l") mesh = LetterL();
  if (name == "beams") mesh = Beams();
  if (name == "sphere_cone") mesh = SphereAndCone();
  if (name == "surface") mesh = FunctionSurface();
  if (name == "steps") mesh = Steps();
  if (mesh) mesh->name = std::string(name) + ".dat";
  return mesh;
}

Mesh GenerateSphere(int latitudeBands, int longitudeBands) {
  Mesh mesh;
  AddSphere(mesh, {}, 1.0, latitudeBands, longitudeBands);
  mesh.name = "sphere";
  return mesh;
}

Mesh GenerateTriangleSphere(size_t triangleCount) {
  // A UV sphere with L latitude and M longitude bands has 2 M (L - 1) triangles
  // once its quads are split; L = M / 2 keeps the quads near square.
  const auto longitude =
      std::max(4, static_cast<int>(std::lround(std::sqrt(static_cast<double>(triangleCount)))));
  const int latitude = std::max(
      2, static_cast<int>(std::lround(static_cast<double>(triangleCount) / (2.0 * longitude))) + 1);
  const Mesh bands = GenerateSphere(latitude, longitude);
  Mesh mesh;
  mesh.name = "sphere";
  mesh.verticesFile = bands.verticesFile;
  mesh.faceCorners.reserve(bands.faceCorners.size() * 3 / 2);
  mesh.faceStarts.reserve(2 * bands.FaceCount() + 1);
  mesh.edgeHidden.reserve(bands.faceCorners.size() * 3 / 2);
  for (size_t f = 0; f < bands.FaceCount(); ++f) {
    const auto corners = bands.Face(f);
    for (size_t i = 1; i + 1 < corners.size(); ++i) {
      mesh.AddFace(std::array<uint32_t, 3>{corners[0], corners[i], corners[i + 1]});
    }
  }
  return mesh;
}

}  // namespace termshade
