// Micro-benchmarks of the frame loop (Google Benchmark): one thread, 160x48 cells.
#include <benchmark/benchmark.h>

#include "geometry/FitCamera.h"
#include "io/SceneGenerators.h"
#include "raster/Renderer.h"

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
  for (auto _ : state) {
    view.theta += 0.01;
    renderer.Render(scene, FitCamera(scene, view, 160, 48, 2.0), options, depth, cells);
    benchmark::DoNotOptimize(cells.FaceNumbers().data());
  }
  state.counters["triangles"] = static_cast<double>(scene.triangles.size());
}

void BM_SphereCone(benchmark::State& state) {
  static const Scene scene = PrepareScene(*GenerateScene("sphere_cone"));
  RenderTurntable(state, scene, static_cast<Method>(state.range(0)));
}
BENCHMARK(BM_SphereCone)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

void BM_Sphere200k(benchmark::State& state) {
  static const Scene scene = PrepareScene(GenerateSphere(317, 317));
  RenderTurntable(state, scene, Method::kZBuffer);
}
BENCHMARK(BM_Sphere200k)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace termshade

BENCHMARK_MAIN();
