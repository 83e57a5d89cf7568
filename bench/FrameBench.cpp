#include "FrameBench.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <random>

#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "geometry/RayBvh.h"
#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
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

double FrameMs(const Scene& scene, const Camera& camera, const FrameCase& frameCase,
               Renderer& renderer, DepthBuffer& depth, CellBuffer& cells) {
  RenderOptions options;
  options.method = Method::kAuto;
  options.keepDepth = false;  // as the viewer draws
  options.threads = frameCase.threads;
  options.variant.clusters = frameCase.clusters;
  options.variant.clusterCulling = frameCase.culling;
  options.variant.hierarchy = frameCase.hierarchy;
  const Clock::time_point start = Clock::now();
  renderer.Render(scene, camera, options, depth, cells);
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Per case, its time on each view of a turntable; the cases take turns on
// each view, in an order shuffled every view (fixed seed), so no case always
// runs after the same other one (whose caches and branch history it would inherit).
std::vector<std::vector<double>> ViewMs(const Scene& scene, int width, int height,
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
      const double elapsed = FrameMs(scene, camera, cases[k], renderers[k], depth, cells);
      if (frame > 0) ms[k].push_back(elapsed);  // the first frame warms caches and threads
    }
  }
  return ms;
}

// As the viewer orbits: runs of kRunFrames frames of one case, theta
// advancing by the turntable's step, the two cases' runs alternating (the
// first of each run, after the other case's, not timed). Per run pair, the
// median of each run's frames; returns those medians per case.
constexpr int kRunFrames = 8;
constexpr double kTurntableStepRadians = 0.04;  // ViewerState's

std::array<std::vector<double>, 2> RunMs(const Scene& scene, int width, int height,
                                         const std::array<FrameCase, 2>& cases, int runPairs) {
  std::array<Renderer, 2> renderers;
  std::array<std::vector<double>, 2> ms;
  DepthBuffer depth;
  CellBuffer cells;
  depth.Resize(width, height);
  cells.Resize(width, height);
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  for (int pair = 0; pair < runPairs; ++pair) {
    for (int turn = 0; turn < 2; ++turn) {
      const size_t k =
          static_cast<size_t>(turn ^ (pair & 1));  // each case first in every other pair
      ViewParams runView = view;
      std::vector<double> run;
      for (int frame = 0; frame <= kRunFrames; ++frame) {
        runView.theta += kTurntableStepRadians;
        const Camera camera = FitCamera(scene, runView, width, height, 2.0);
        const double elapsed = FrameMs(scene, camera, cases[k], renderers[k], depth, cells);
        if (frame > 0) run.push_back(elapsed);
      }
      ms[k].push_back(Median(run));
    }
    view.theta += kTurntableStepRadians * kRunFrames;
  }
  return ms;
}

// The median over views of one case's time over another's on the same view:
// a drift of the machine's speed during the run cancels out.
double MedianRatio(const std::vector<double>& numerator, const std::vector<double>& denominator) {
  std::vector<double> ratios(numerator.size());
  for (size_t i = 0; i < ratios.size(); ++i) ratios[i] = numerator[i] / denominator[i];
  return Median(ratios);
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
  std::printf(
      " rays / clusters, all | rays, all / 1 thread | clusters, all / 1 thread | hierarchy: build "
      "ms, MB |\n|---|---|---|");
  for (size_t k = 0; k <= cases.size() + 3; ++k) std::printf("---|");
  std::printf("\n");
  std::string runRows;
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
      const std::vector<std::vector<double>> viewMs =
          ViewMs(named.scene, width, height, cases, options.frames);
      std::vector<double> ms(viewMs.size());
      std::transform(viewMs.begin(), viewMs.end(), ms.begin(), Median<double>);
      std::printf("| %s | %zu | %s |", named.name.c_str(), named.scene.triangles.size(),
                  size.c_str());
      for (const double m : ms) std::printf(" %.3f |", m);
      std::printf(" %.2f | %.3f | %.3f | %.0f, %.1f |\n", ms[1] / ms[3],
                  MedianRatio(viewMs[1], viewMs[0]), MedianRatio(viewMs[3], viewMs[2]), buildMs,
                  megabytes);
      std::fflush(stdout);
      for (const size_t first : {size_t{0}, size_t{2}}) {  // rays, clusters: 1 thread, all
        const auto runMs = RunMs(named.scene, width, height, {cases[first], cases[first + 1]},
                                 std::max(3, options.frames / 4));
        char row[256];
        std::snprintf(row, sizeof row, "| %s | %zu | %s | %s | %.3f | %.3f | %.3f |\n",
                      named.name.c_str(), named.scene.triangles.size(), size.c_str(),
                      first == 0 ? "rays" : "clusters", Median(runMs[0]), Median(runMs[1]),
                      MedianRatio(runMs[1], runMs[0]));
        runRows += row;
      }
    }
  }

  std::printf(
      "\nmedians of %d turntable frames (method auto, as the viewer draws); the cases take turns "
      "on each frame, in an order shuffled each frame; all / 1 thread: the median over frames "
      "of the two cases' ratio on the same frame; all threads = %d\n",
      options.frames, all);
  std::printf(
      "\nThreads as the viewer orbits: runs of %d frames of one thread count (theta + %.2f a "
      "frame), the two counts' runs alternating; medians of the runs' medians, and the median "
      "over run pairs of all / 1 thread\n\n| model | triangles | cells | method | 1 thread, ms | "
      "all, ms | all / 1 thread |\n|---|---|---|---|---|---|---|\n%s",
      kRunFrames, kTurntableStepRadians, runRows.c_str());
  return 0;
}

}  // namespace termshade
