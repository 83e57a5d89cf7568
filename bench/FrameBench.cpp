#include "FrameBench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <random>

#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "geometry/RayBvh.h"
#include "io/ModelLoader.h"
#include "io/SceneGenerators.h"
#include "raster/Renderer.h"
#include "raster/WorkerPool.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

struct FrameCase {
  const char* name;
  int threads;
  bool clusters;
  bool culling;
  HierarchyUse hierarchy;
};

struct BenchScene {
  std::string name;
  Scene scene;
};

// Medians per case over a turntable; the cases take turns on each view, in
// an order shuffled every view (fixed seed), so no case always runs after
// the same other one (whose caches and branch history it would inherit).
std::vector<double> MedianMs(const Scene& scene, int width, int height,
                             const std::vector<FrameCase>& cases, int frames) {
  std::vector<Renderer> renderers(cases.size());
  std::vector<std::vector<double>> ms(cases.size());
  DepthBuffer depth;
  CellBuffer cells;
  depth.Resize(width, height);
  cells.Resize(width, height);
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  std::vector<size_t> order(cases.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::mt19937 shuffler(20261202);
  for (int frame = 0; frame <= frames; ++frame) {
    view.theta += 0.1;
    const Camera camera = FitCamera(scene, view, width, height, 2.0);
    std::shuffle(order.begin(), order.end(), shuffler);
    for (const size_t k : order) {
      RenderOptions options;
      options.method = Method::kAuto;
      options.keepDepth = false;  // as the viewer draws
      options.threads = cases[k].threads;
      options.variant.clusters = cases[k].clusters;
      options.variant.clusterCulling = cases[k].culling;
      options.variant.hierarchy = cases[k].hierarchy;
      const Clock::time_point start = Clock::now();
      renderers[k].Render(scene, camera, options, depth, cells);
      const double elapsed =
          std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      if (frame > 0) ms[k].push_back(elapsed);  // the first frame warms caches and threads
    }
  }
  std::vector<double> medians;
  for (const auto& m : ms) medians.push_back(Median(m));
  return medians;
}

}  // namespace

int RunFrameBench(const FrameBenchOptions& options) {
  const int all = ResolvedThreadCount(options.threads);
  std::vector<BenchScene> scenes;
  std::vector<size_t> triangleCounts = options.triangleCounts;
  if (options.modelPaths.empty() && triangleCounts.empty()) {
    scenes.push_back({"demo sphere_cone", PrepareScene(*GenerateScene("sphere_cone"))});
    triangleCounts = {200000, 2000000};
  }
  for (const std::string& path : options.modelPaths) {
    Loaded<Mesh> mesh = LoadModelFile(path);
    if (!mesh.Ok()) {
      std::cerr << mesh.Error().ToString() << "\n";
      return 1;
    }
    scenes.push_back({path, PrepareScene(std::move(mesh.Value()))});
  }
  for (const size_t triangles : triangleCounts) {
    scenes.push_back({"sphere " + std::to_string(triangles / 1000) + "k",
                      PrepareScene(GenerateTriangleSphere(triangles))});
  }
  const std::vector<FrameCase> cases{
      {"rays, 1 thread", 1, true, true, HierarchyUse::kAlways},
      {"rays, all", all, true, true, HierarchyUse::kAlways},
      {"clusters, 1 thread", 1, true, true, HierarchyUse::kNever},
      {"clusters, all", all, true, true, HierarchyUse::kNever},
      {"1 thread, no culling", 1, true, false, HierarchyUse::kNever},
      {"all, no culling", all, true, false, HierarchyUse::kNever},
      {"face loop (before)", 1, false, false, HierarchyUse::kNever},
      {"measured choice, all", all, true, true, HierarchyUse::kWhenFaster},  // the default
  };
  std::printf("| model | triangles | cells |");
  for (const FrameCase& c : cases) std::printf(" %s, ms |", c.name);
  std::printf(" rays / clusters, all | hierarchy: build ms, MB |\n|---|---|---|");
  for (size_t k = 0; k <= cases.size() + 1; ++k) std::printf("---|");
  std::printf("\n");
  for (BenchScene& named : scenes) {
    // Every scene gets its hierarchy here, below RayCastStage::Faster too, to show the
    // crossover.
    const Clock::time_point buildStart = Clock::now();
    auto bvh = std::make_shared<const RayBvh>(BuildRayBvh(named.scene));
    const double buildMs =
        std::chrono::duration<double, std::milli>(Clock::now() - buildStart).count();
    const double megabytes = static_cast<double>(bvh->Bytes()) / (1 << 20);
    named.scene.hierarchy.Attach(std::move(bvh));
    for (const std::string& size : options.sizes) {
      int width = 0, height = 0;
      if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1) {
        std::cerr << "termshade bench frame: size '" << size << "' is not COLSxROWS\n";
        return 1;
      }
      const std::vector<double> ms = MedianMs(named.scene, width, height, cases, options.frames);
      std::printf("| %s | %zu | %s |", named.name.c_str(), named.scene.triangles.size(),
                  size.c_str());
      for (const double m : ms) std::printf(" %.3f |", m);
      std::printf(" %.2f | %.0f, %.1f |\n", ms[1] / ms[3], buildMs, megabytes);
      std::fflush(stdout);
    }
  }
  std::printf(
      "\nmedians of %d turntable frames (method auto, as the viewer draws); the cases take turns "
      "on each frame, in an order shuffled each frame; all threads = %d\n",
      options.frames, all);
  return 0;
}

}  // namespace termshade
