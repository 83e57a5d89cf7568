#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "raster/RenderOptions.h"
#include "raster/Renderer.h"

namespace termshade {

/// Shade steps a snapshot sample records: Lambert intensity in 256 steps (the
/// cell buffer's own resolution).
constexpr int kSnapshotShadeSteps = 256;

/// What a snapshot compares for one view (docs/snapshot-testing.md): a grid
/// of samples, k x m a cell, row-major, each with the 1-based face it shows
/// (0 = background) and that face's Lambert shade in kSnapshotShadeSteps
/// steps (0 for background). Lambert, whatever the frame's shade mode: a
/// contrast frame rescales every face when one face appears or goes.
struct SnapshotSamples {
  int widthSamples = 0;
  int heightSamples = 0;
  std::vector<uint32_t> faces;
  std::vector<uint8_t> shades;

  size_t Index(int x, int y) const { return static_cast<size_t>(y) * widthSamples + x; }
  bool operator==(const SnapshotSamples&) const = default;
};

/// The samples of a widthCells x heightCells frame seen by `camera`, on a
/// grid of `grid` samples a cell: one sample a cell of the camera scaled by
/// the grid (SampleCamera), drawn with `options`' method, culling and threads.
SnapshotSamples ProbeSnapshotSamples(Renderer& renderer, const Scene& scene, const Camera& camera,
                                     int widthCells, int heightCells, SampleGrid grid,
                                     const RenderOptions& options);

}  // namespace termshade
