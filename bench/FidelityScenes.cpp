#include "FidelityScenes.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"

namespace termshade {
namespace {

constexpr const char* kDuckPath = "/usr/share/assimp/models/Collada/duck.dae";

// A (2, 3) torus knot tube: curved, self-occluding, thin in places, 19,200 triangles.
Mesh TorusKnot() {
  constexpr int kAlong = 320, kAround = 30;
  constexpr double kTube = 0.28;
  Mesh mesh;
  auto curve = [](double t) {
    const double r = 2.0 + std::cos(3 * t);
    return Vec3{r * std::cos(2 * t), r * std::sin(2 * t), std::sin(3 * t)};
  };
  for (int i = 0; i < kAlong; ++i) {
    const double t = 2 * std::numbers::pi * i / kAlong, dt = 1e-4;
    const Vec3 p = curve(t), tangent = Normalized(curve(t + dt) - curve(t - dt));
    const Vec3 side = Normalized(Cross(tangent, Vec3{0, 0, 1}));
    const Vec3 up = Cross(side, tangent);
    for (int j = 0; j < kAround; ++j) {
      const double a = 2 * std::numbers::pi * j / kAround;
      mesh.verticesFile.push_back(p + (side * std::cos(a) + up * std::sin(a)) * kTube);
    }
  }
  for (int i = 0; i < kAlong; ++i) {
    for (int j = 0; j < kAround; ++j) {
      const auto at = [&](int ii, int jj) {
        return static_cast<uint32_t>((ii % kAlong) * kAround + jj % kAround);
      };
      mesh.AddFace(std::array<uint32_t, 4>{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

// A 256 x 128 texture of 16 x 8 squares, orange and blue, with a thin white
// line through the middle of each square: edges at every scale a view shows.
TextureImage CheckerTexture() {
  constexpr uint32_t kWidth = 256, kHeight = 128, kSquare = 16;
  TextureImage image;
  image.widthTexels = kWidth;
  image.heightTexels = kHeight;
  image.srgbTexels.reserve(size_t{kWidth} * kHeight * 3);
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const bool orange = ((x / kSquare) + (y / kSquare)) % 2 == 0;
      const bool line = y % kSquare == kSquare / 2;
      const std::array<uint8_t, 3> texel = line     ? std::array<uint8_t, 3>{240, 240, 240}
                                           : orange ? std::array<uint8_t, 3>{235, 130, 40}
                                                    : std::array<uint8_t, 3>{40, 80, 190};
      image.srgbTexels.insert(image.srgbTexels.end(), texel.begin(), texel.end());
    }
  }
  return image;
}

// A UV sphere (48 around, 24 down) wearing CheckerTexture; its seam and poles
// get their own corner coordinates.
Mesh CheckerGlobe() {
  constexpr int kAround = 48, kDown = 24;
  Mesh mesh;
  for (int j = 0; j <= kDown; ++j) {
    const double polar = std::numbers::pi * j / kDown;
    for (int i = 0; i < kAround; ++i) {
      const double azimuth = 2 * std::numbers::pi * i / kAround;
      mesh.verticesFile.push_back(Vec3{std::sin(polar) * std::cos(azimuth),
                                       std::sin(polar) * std::sin(azimuth), std::cos(polar)});
    }
  }
  mesh.textures = {"checker"};
  mesh.textureImages = {CheckerTexture()};
  const auto vertex = [](int i, int j) { return static_cast<uint32_t>(j * kAround + i % kAround); };
  const auto uv = [](double i, int j) {
    return std::array<float, 2>{static_cast<float>(i / kAround),
                                1.0F - static_cast<float>(j) / kDown};
  };
  for (int j = 0; j < kDown; ++j) {
    for (int i = 0; i < kAround; ++i) {
      // Counter-clockwise seen from outside; at a pole a triangle whose pole
      // corner takes the middle of its span of u.
      std::vector<uint32_t> corners;
      std::vector<std::array<float, 2>> uvs;
      const auto add = [&](int ii, int jj, double uAt) {
        corners.push_back(vertex(ii, jj));
        uvs.push_back(uv(uAt, jj));
      };
      if (j > 0) add(i + 1, j, i + 1);
      add(i, j, j == 0 ? i + 0.5 : i);
      if (j + 1 < kDown) {
        add(i, j + 1, i);
        add(i + 1, j + 1, i + 1);
      } else {
        add(i, j + 1, i + 0.5);
      }
      mesh.AddFace(corners);
      mesh.faceTextures.push_back(0);
      mesh.cornerUvs.insert(mesh.cornerUvs.end(), uvs.begin(), uvs.end());
    }
  }
  return mesh;
}

void AddLoaded(std::vector<NamedScene>& scenes, const std::string& name, const std::string& path) {
  Loaded<Mesh> mesh = LoadModelFile(path);
  if (!mesh.Ok()) {
    std::cerr << mesh.Error().ToString() << "\n";
    return;
  }
  scenes.push_back({name, PrepareScene(std::move(mesh.Value()))});
}

}  // namespace

std::vector<NamedScene> FidelityScenes(const std::string& dataDirectory) {
  std::vector<NamedScene> scenes;
  for (const std::string& name : GeneratedSceneNames()) {
    std::string path = dataDirectory;
    path.append("/").append(name).append(".dat");
    AddLoaded(scenes, name, path);
  }
  scenes.push_back({"torus knot 19k", PrepareScene(TorusKnot())});
  scenes.push_back({"checker globe", PrepareScene(CheckerGlobe())});
  std::error_code error;
  if (std::filesystem::is_regular_file(kDuckPath, error)) AddLoaded(scenes, "duck", kDuckPath);
  return scenes;
}

}  // namespace termshade
