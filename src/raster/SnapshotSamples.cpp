#include "raster/SnapshotSamples.h"

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"

namespace termshade {

SnapshotSamples ProbeSnapshotSamples(Renderer& renderer, const Scene& scene, const Camera& camera,
                                     int widthCells, int heightCells, SampleGrid grid,
                                     const RenderOptions& options) {
  RenderOptions probe;
  probe.method = options.method;
  probe.cullBackFaces = options.cullBackFaces;
  probe.threads = options.threads;
  probe.shade = ShadeMode::kLambert;
  probe.keepDepth = false;
  SnapshotSamples samples;
  samples.widthSamples = widthCells * grid.across;
  samples.heightSamples = heightCells * grid.down;
  CellBuffer cells(samples.widthSamples, samples.heightSamples);
  DepthBuffer depth;
  depth.Resize(samples.widthSamples, samples.heightSamples);
  renderer.Render(scene, SampleCamera(camera, grid), probe, depth, cells);
  samples.faces = cells.FaceNumbers();
  samples.shades.resize(samples.faces.size());
  constexpr int kIntensityPerStep = 256 / kSnapshotShadeSteps;
  for (size_t i = 0; i < samples.faces.size(); ++i) {
    samples.shades[i] = samples.faces[i] == 0
                            ? 0
                            : static_cast<uint8_t>(cells.Intensities()[i] / kIntensityPerStep);
  }
  return samples;
}

}  // namespace termshade
