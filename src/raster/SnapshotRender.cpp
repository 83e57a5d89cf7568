#include "raster/SnapshotRender.h"

#include "geometry/FitCamera.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/Renderer.h"

namespace termshade {

RenderOptions SnapshotSettings::FrameOptions() const {
  RenderOptions options;
  options.method = method;
  options.shade = shade;
  options.glyphs = glyphs;
  options.ramp = ShadeRamp(ramp);
  options.cullBackFaces = cullBackFaces;
  options.threads = threads;
  options.keepDepth = false;
  return options;
}

std::vector<SnapshotFrame> RenderSnapshot(const Scene& scene, const SnapshotSettings& settings) {
  const RenderOptions options = settings.FrameOptions();
  Renderer renderer;
  CellBuffer cells(settings.widthCells, settings.heightCells);
  DepthBuffer depth;
  depth.Resize(settings.widthCells, settings.heightCells);
  std::vector<SnapshotFrame> frames;
  for (const std::string& name : settings.views) {
    const auto view = SnapshotViewFor(name, settings.theta, settings.phi);
    if (!view) continue;
    ViewParams params = DefaultView(scene.diagonalModelUnits);
    params.theta = view->theta;
    params.phi = view->phi;
    const Camera camera =
        FitCamera(scene, params, settings.widthCells, settings.heightCells, settings.cellAspect);
    SnapshotFrame frame;
    frame.view = *view;
    renderer.Render(scene, camera, options, depth, cells);
    for (int row = 0; row < settings.heightCells; ++row)
      frame.textRows.push_back(cells.RowText(row));
    frame.samples = ProbeSnapshotSamples(renderer, scene, camera, settings.widthCells,
                                         settings.heightCells, settings.samples, options);
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace termshade
