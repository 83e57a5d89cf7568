#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/UpAxis.h"

namespace termshade {

/// `termshade bench models FILE...`: what each model file gives as loaded
/// (up axis, parts turned outward, colours) and its frame time; one
/// tab-separated row per file, for tests/tools/corpus_table.py.
struct ModelsBenchOptions {
  std::vector<std::string> modelPaths;
  int widthCells = 160;
  int heightCells = 48;
  std::optional<UpAxis> upAxis;
};

int RunModelsBench(const ModelsBenchOptions& options);

}  // namespace termshade
