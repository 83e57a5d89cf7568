#include "raster/SnapshotRender.h"

#include "geometry/FitCamera.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/Renderer.h"

namespace termshade {
namespace {

// Each cell's texture colour at its center: a ramp frame with colours shown.
std::vector<uint32_t> TextureColours(const Scene& scene, const Camera& camera, int width,
                                     int height, const RenderOptions& frameOptions) {
  RenderOptions options = frameOptions;
  options.glyphs = GlyphMode::kRamp;
  options.twoColour = true;
  options.textures = true;
  CellBuffer cells(width, height);
  DepthBuffer depth;
  depth.Resize(width, height);
  Renderer().Render(scene, camera, options, depth, cells);
  std::vector<uint32_t> colours(static_cast<size_t>(width) * height, 0U);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col)
      colours[cells.Index(col, row)] = cells.ForeAlbedo(col, row);
  }
  return colours;
}

}  // namespace

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
    if (scene.textures.Any())
      frame.textureColours =
          TextureColours(scene, camera, settings.widthCells, settings.heightCells, options);
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace termshade
