#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/UpAxis.h"
#include "io/read/LoadOptions.h"

namespace termshade {

/// `termshade info MODEL... [--format text|json]`: what a model file holds,
/// nothing drawn.
struct InfoCommandOptions {
  std::vector<std::string> modelPaths;
  std::string format = "text";   ///< text (for people) or json (one object a line)
  std::optional<UpAxis> upAxis;  ///< unset: each file's own (SPEC 10)
  LoadLimits loadLimits;         ///< --memory-budget, --import-seconds
  std::string reader = "auto";   ///< --reader auto|assimp
};

/// Loads and prepares each model as the viewer would and reports its reader,
/// counts, bounds, up axis, orientation, open edges, colours, load time and
/// peak memory. Returns 0, or 1 when a model could not be read (the others
/// are still reported).
int RunInfoCommand(const InfoCommandOptions& options);

}  // namespace termshade
