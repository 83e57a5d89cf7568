#include "FrameTiming.h"

#include <chrono>
#include <vector>

#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "raster/Renderer.h"

namespace termshade {

double MedianTurntableFrameMs(const Scene& scene, int widthCells, int heightCells,
                              int timedFrames) {
  using Clock = std::chrono::steady_clock;
  RenderOptions render;
  render.keepDepth = false;
  Renderer renderer;
  DepthBuffer depth;
  CellBuffer cells;
  depth.Resize(widthCells, heightCells);
  cells.Resize(widthCells, heightCells);
  std::vector<double> frameMs;
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  for (int frame = 0; frame <= timedFrames; ++frame) {
    view.theta += 0.1;
    const Camera camera = FitCamera(scene, view, widthCells, heightCells, 2.0);
    const Clock::time_point start = Clock::now();
    renderer.Render(scene, camera, render, depth, cells);
    if (frame > 0) {
      frameMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
  }
  return Median(frameMs);
}

}  // namespace termshade
