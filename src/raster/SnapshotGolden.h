#pragma once

#include <optional>
#include <vector>

#include "geometry/UpAxis.h"
#include "raster/SnapshotRender.h"

namespace termshade {

/// The golden file format's version (first line `termshade-snapshot/1`).
constexpr int kSnapshotFormatVersion = 1;

/// A snapshot golden (docs/snapshot-testing.md#the-golden-file): the options
/// that made it, and per view the text frame and the compared samples.
struct SnapshotGolden {
  SnapshotSettings settings;
  std::optional<UpAxis> upAxis;  ///< unset: the model file's own (SPEC 10)
  std::vector<SnapshotFrame> frames;
};

}  // namespace termshade
