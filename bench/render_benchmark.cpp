// Micro-benchmarks of the frame loop (Google Benchmark): one thread, 160x48 cells.
#include <benchmark/benchmark.h>

#include <chrono>

#include "geometry/FitCamera.h"
#include "geometry/ViewingTransform.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/Renderer.h"
#include "raster/WorkerPool.h"

namespace termshade {
namespace {

void RenderTurntable(benchmark::State& state, const Scene& scene, Method method) {
  RenderOptions options;
  options.method = method;
  Renderer renderer;
  CellBuffer cells(160, 48);
  DepthBuffer depth;
  depth.Resize(160, 48);
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    view.theta += 0.01;
    renderer.Render(scene, FitCamera(scene, view, 160, 48, 2.0), options, depth, cells);
    benchmark::DoNotOptimize(cells.FaceNumbers().data());
  }
  state.counters["triangles"] = static_cast<double>(scene.triangles.size());
}

void BM_SphereCone(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  static const Scene scene = PrepareScene(*GenerateScene("sphere_cone"));
  RenderTurntable(state, scene, static_cast<Method>(state.range(0)));
}
BENCHMARK(BM_SphereCone)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

void BM_Sphere200k(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  static const Scene scene = PrepareScene(GenerateSphere(317, 317));
  RenderTurntable(state, scene, Method::kZBuffer);
}
BENCHMARK(BM_Sphere200k)->Unit(benchmark::kMicrosecond);

// The baseline of issue 4: a plain loop that only transforms every vertex,
// then bounds and tests every triangle against the view, drawing nothing.
void BM_PlainLoop200k(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  static const Scene scene = PrepareScene(GenerateSphere(317, 317));
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  std::vector<float> projected(scene.verticesWorld.size() * 2);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    view.theta += 0.01;
    const Camera camera = FitCamera(scene, view, 160, 48, 2.0);
    const Mat4 m = EyeFromWorld(camera.view);
    const Projection& p = camera.projection;
    for (size_t i = 0; i < scene.verticesWorld.size(); ++i) {
      const Vec3 e = TransformPoint(m, scene.verticesWorld[i]);
      const double w = -1.0 / e.z;
      projected[2 * i] = static_cast<float>(p.cx + p.d * e.x * w);
      projected[2 * i + 1] = static_cast<float>(p.cy - p.d / p.cellAspect * e.y * w);
    }
    int inView = 0;
    for (const SceneTriangle& t : scene.triangles) {
      float low[2] = {1e30F, 1e30F}, high[2] = {-1e30F, -1e30F};
      for (uint32_t v : t.vertices) {
        for (int k = 0; k < 2; ++k) {
          low[k] = std::min(low[k], projected[2 * v + k]);
          high[k] = std::max(high[k], projected[2 * v + k]);
        }
      }
      inView += high[0] >= 0 && low[0] < 160 && high[1] >= 0 && low[1] < 48 ? 1 : 0;
    }
    benchmark::DoNotOptimize(inView);
  }
}
BENCHMARK(BM_PlainLoop200k)->Unit(benchmark::kMicrosecond);

// A pool's hand-over: Run of a job that keeps each of two workers busy for
// 200 us, back to back, so the time above 200 us is the pool's own; with two
// pools taking turns (two renderers), each pool's workers idle while the
// other's run.
void BusyFor(std::chrono::microseconds span) {
  const auto end = std::chrono::steady_clock::now() + span;
  while (std::chrono::steady_clock::now() < end) {
  }
}

void BM_PoolHandOver(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  WorkerPool first(2), second(2);
  const bool twoPools = state.range(0) != 0;
  auto job = [](int) { BusyFor(std::chrono::microseconds(200)); };
  bool turn = false;
  for (auto _ : state) {
    (twoPools && turn ? second : first).Run(job);
    turn = !turn;
  }
}
BENCHMARK(BM_PoolHandOver)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace termshade

BENCHMARK_MAIN();
