#include "SnapshotBench.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <random>
#include <set>

#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/SnapshotCompare.h"
#include "raster/SnapshotRender.h"

namespace termshade {
namespace {

// Corpus models the bench takes when they are installed (assimp-testmodels).
constexpr const char* kCorpusModels[] = {
    "/usr/share/assimp/models/OBJ/spider.obj",
    "/usr/share/assimp/models/PLY/Wuson.ply",
    "/usr/share/assimp/models/STL/Spider_binary.stl",
    "/usr/share/assimp/models/OFF/Cube.off",
};

std::vector<std::string> DefaultModels(const std::string& dataDirectory) {
  std::vector<std::string> paths;
  for (const std::string& name : GeneratedSceneNames()) {
    paths.push_back(dataDirectory + "/" + name + ".dat");
  }
  for (const char* path : kCorpusModels) {
    if (access(path, R_OK) == 0) paths.emplace_back(path);
  }
  return paths;
}

// Vertices at a corner of a face the default view shows.
std::vector<uint32_t> SeenVertices(const Mesh& mesh, const SnapshotFrame& defaultView) {
  std::set<uint32_t> faces(defaultView.samples.faces.begin(), defaultView.samples.faces.end());
  faces.erase(0);
  std::set<uint32_t> vertices;
  for (const uint32_t face : faces) {
    if (face > mesh.FaceCount()) continue;
    for (const uint32_t v : mesh.Face(face - 1)) vertices.insert(v);
  }
  return {vertices.begin(), vertices.end()};
}

std::string Percent(int caught, int trials) {
  if (trials == 0) return "-";
  char text[16];
  // Never "100%" for 219 of 220, nor "0%" for 1 of 220.
  const double percent = 100.0 * caught / trials;
  std::snprintf(text, sizeof text, caught > 0 && caught < trials ? "%.1f%%" : "%.0f%%", percent);
  return text;
}

}  // namespace

int RunSnapshotBench(const SnapshotBenchOptions& options) {
  std::vector<SnapshotTolerance> tolerances;
  for (const std::string& text : options.tolerances) {
    const auto tolerance = ParseSnapshotTolerance(text);
    if (!tolerance) {
      std::cerr << "termshade bench snapshots: bad tolerance " << SanitizeForTerminal(text) << "\n";
      return 2;
    }
    tolerances.push_back(*tolerance);
  }
  const std::vector<std::string> paths =
      options.modelPaths.empty() ? DefaultModels(options.dataDirectory) : options.modelPaths;
  SnapshotSettings settings;
  settings.widthCells = options.widthCells;
  settings.heightCells = options.heightCells;
  const size_t sizes = options.moveShares.size();
  // caught[size][tolerance], over all models; and per model at the default tolerance.
  std::vector<std::vector<int>> caught(sizes, std::vector<int>(tolerances.size(), 0));
  std::vector<int> trialsAt(sizes, 0);
  std::vector<std::string> modelRows;
  std::mt19937_64 random(20240530);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const std::string& path : paths) {
    Loaded<Mesh> loaded = LoadModelFile(path);
    if (!loaded.Ok()) {
      std::cerr << loaded.Error().ToString() << "\n";
      continue;
    }
    const Mesh original = std::move(loaded.Value());
    const Scene scene = PrepareScene(original);
    const double diagonal = scene.diagonalModelUnits;
    const std::vector<SnapshotFrame> golden = RenderSnapshot(scene, settings);
    const std::vector<uint32_t> seen = SeenVertices(original, golden.front());
    if (seen.empty()) continue;
    std::string row = "| ";
    row += path.substr(path.find_last_of('/') + 1);
    row += " | ";
    row += std::to_string(original.FaceCount());
    row += " |";
    for (size_t s = 0; s < sizes; ++s) {
      int caughtHere = 0;
      for (int trial = 0; trial < options.trials; ++trial) {
        Mesh moved = original;
        const uint32_t vertex = seen[random() % seen.size()];
        Vec3 direction{gauss(random), gauss(random), gauss(random)};
        const double length = std::sqrt(direction.x * direction.x + direction.y * direction.y +
                                        direction.z * direction.z);
        const double scale = options.moveShares[s] * diagonal / std::max(length, 1e-12);
        moved.verticesFile[vertex].x += direction.x * scale;
        moved.verticesFile[vertex].y += direction.y * scale;
        moved.verticesFile[vertex].z += direction.z * scale;
        const std::vector<SnapshotFrame> actual =
            RenderSnapshot(PrepareScene(std::move(moved)), settings);
        ++trialsAt[s];
        for (size_t t = 0; t < tolerances.size(); ++t) {
          const bool differs = !CompareSnapshotFrames(golden, actual, tolerances[t]).Passed();
          caught[s][t] += differs ? 1 : 0;
          if (t == 0 && differs) ++caughtHere;
        }
      }
      row += ' ';
      row += Percent(caughtHere, options.trials);
      row += " |";
    }
    modelRows.push_back(row);
    std::cerr << "." << std::flush;
  }
  std::cerr << "\n";
  std::string header = "| move (share of the diagonal) |", rule = "| --- |";
  for (const std::string& t : options.tolerances) {
    header += " --tolerance " + t + " |";
    rule += " --- |";
  }
  std::cout << "Detection rate, all models (" << options.trials << " moves per model and size, "
            << options.widthCells << "x" << options.heightCells << ", views "
            << "default opposite top bottom):\n\n"
            << header << "\n"
            << rule << "\n";
  for (size_t s = 0; s < sizes; ++s) {
    char share[32];
    std::snprintf(share, sizeof share, "%g", options.moveShares[s]);
    std::cout << "| " << share << " |";
    for (size_t t = 0; t < tolerances.size(); ++t) {
      std::cout << " " << Percent(caught[s][t], trialsAt[s]) << " (" << caught[s][t] << "/"
                << trialsAt[s] << ") |";
    }
    std::cout << "\n";
  }
  std::cout << "\nDetection rate per model at the default tolerance (0):\n\n| model | faces |";
  for (const double share : options.moveShares) std::cout << " " << share << " |";
  std::cout << "\n| --- | --- |";
  for (size_t s = 0; s < sizes; ++s) std::cout << " --- |";
  std::cout << "\n";
  for (const std::string& row : modelRows) std::cout << row << "\n";
  return 0;
}

}  // namespace termshade
